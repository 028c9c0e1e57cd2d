// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
// The DEM script check (demScriptCheck): a script that can couple passes
// and says what it found; each way a script cannot couple stops with a
// message that names the file, the line and what is expected.

#include <gtest/gtest.h>
#include "testMain.H"
#include "demScriptCheck.H"
#include "OFstream.H"
#include "OSspecific.H"

#include <cstdlib>

using namespace Foam;
using namespace Foam::demCoupling;
using testing_demCoupling::errorMessage;

namespace
{

// A fresh folder for the scripts of one test
fileName scratch(const std::string& name)
{
    const fileName dir(fileName(std::getenv("TMPDIR") ? std::getenv("TMPDIR")
                                : "/tmp")/"demScriptCheckTest"/name);
    if (isDir(dir))
    {
        rmDir(dir);
    }
    mkDir(dir);
    return dir;
}

void write(const fileName& file, const std::string& text)
{
    OFstream os(file);
    os << text.c_str();
}


const dictionary& couplingDict()
{
    static dictionary dict;
    return dict;
}

bool has(const std::string& msg, const std::string& what)
{
    return msg.find(what) != std::string::npos;
}

} // End anonymous namespace


TEST(demScriptCheck, WordsDropComments)
{
    const wordList w(demScriptCheck::words("  fix  cfd all\tcouple/cfd # x y"));
    ASSERT_EQ(w.size(), 4);
    EXPECT_EQ(w[0], "fix");
    EXPECT_EQ(w[3], "couple/cfd");
    EXPECT_EQ(demScriptCheck::words("# only a comment").size(), 0);
}


TEST(demScriptCheck, IncludesAndContinuationLinesAreFollowed)
{
    const fileName dir(scratch("good"));
    write(dir/"in.main",
        "atom_style granular\n"
        "include DEM/in.coupling\n"
        "fix ins all insert/pack seed 1 &\n"
        "    insert_every once\n");
    mkDir(dir/"DEM");
    write(dir/"DEM/in.coupling",
        "fix cfd all couple/cfd &\n"
        "    couple_every 25 mpi   # the coupling\n"
        "fix cfd2 all couple/cfd/force/implicit\n");

    const demScriptCheck check(dir/"in.main", dir, couplingDict());
    EXPECT_EQ(check.coupleEvery(), 25);
    EXPECT_TRUE(check.inserts());
}


TEST(demScriptCheck, MissingForceFixIsNamed)
{
    const fileName dir(scratch("noForce"));
    write(dir/"in.main", "fix cfd all couple/cfd couple_every 10 mpi\n");
    const std::string msg = errorMessage
    (
        [&]{ demScriptCheck(dir/"in.main", dir, couplingDict()); }
    );
    EXPECT_TRUE(has(msg, "couple/cfd/force")) << msg;
    EXPECT_TRUE(has(msg, "in.main")) << msg;
    EXPECT_FALSE(has(msg, "'couple/cfd' and")) << msg;
}


TEST(demScriptCheck, BothFixesMissingAreNamed)
{
    const fileName dir(scratch("none"));
    write(dir/"in.main", "atom_style granular\n# fix cfd all couple/cfd\n");
    const std::string msg = errorMessage
    (
        [&]{ demScriptCheck(dir/"in.main", dir, couplingDict()); }
    );
    EXPECT_TRUE(has(msg, "'couple/cfd' and the fix 'couple/cfd/force'"))
        << msg;
}


TEST(demScriptCheck, FileCouplingIsRejectedWithItsLine)
{
    const fileName dir(scratch("file"));
    write(dir/"in.main",
        "atom_style granular\n"
        "fix cfd all couple/cfd couple_every 10 file\n"
        "fix cfd2 all couple/cfd/force\n");
    const std::string msg = errorMessage
    (
        [&]{ demScriptCheck(dir/"in.main", dir, couplingDict()); }
    );
    EXPECT_TRUE(has(msg, "line 2")) << msg;
    EXPECT_TRUE(has(msg, "couple_every <N> mpi")) << msg;
}


TEST(demScriptCheck, CoupleEveryMustBeAWholeNumber)
{
    const fileName dir(scratch("variable"));
    for (const char* n : {"${every}", "0", "2.5"})
    {
        write(dir/"in.main",
            std::string("fix cfd all couple/cfd couple_every ") + n
          + " mpi\nfix cfd2 all couple/cfd/force\n");
        const std::string msg = errorMessage
        (
            [&]{ demScriptCheck(dir/"in.main", dir, couplingDict()); }
        );
        EXPECT_TRUE(has(msg, "whole number")) << n << ": " << msg;
        EXPECT_TRUE(has(msg, n)) << msg;
    }
}


TEST(demScriptCheck, MissingIncludeNamesTheIncludingLine)
{
    const fileName dir(scratch("missingInclude"));
    write(dir/"in.main",
        "atom_style granular\n\ninclude DEM/in.nothere\n");
    const std::string msg = errorMessage
    (
        [&]{ demScriptCheck(dir/"in.main", dir, couplingDict()); }
    );
    EXPECT_TRUE(has(msg, "in.nothere")) << msg;
    EXPECT_TRUE(has(msg, "include on line 3")) << msg;
}


TEST(demScriptCheck, MissingScriptNamesTheKeyword)
{
    const fileName dir(scratch("missingScript"));
    const std::string msg = errorMessage
    (
        [&]{ demScriptCheck(dir/"in.none", dir, couplingDict()); }
    );
    EXPECT_TRUE(has(msg, "demScript")) << msg;
}


TEST(demScriptCheck, SelfIncludeStops)
{
    const fileName dir(scratch("loop"));
    write(dir/"in.main", "include in.main\n");
    const std::string msg = errorMessage
    (
        [&]{ demScriptCheck(dir/"in.main", dir, couplingDict()); }
    );
    EXPECT_TRUE(has(msg, "deeper than 16")) << msg;
}


TEST(demScriptCheck, IncludeWithVariableIsLeftToLiggghts)
{
    const fileName dir(scratch("variableInclude"));
    write(dir/"in.main",
        "include ${dir}/in.x\n"
        "fix cfd all couple/cfd couple_every 10 mpi\n"
        "fix cfd2 all couple/cfd/force\n");
    const demScriptCheck check(dir/"in.main", dir, couplingDict());
    EXPECT_EQ(check.coupleEvery(), 10);
    EXPECT_FALSE(check.inserts());
}
