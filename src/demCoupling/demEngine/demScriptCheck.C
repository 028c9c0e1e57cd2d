// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "demScriptCheck.H"
#include "DynamicList.H"

#include <fstream>

// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * //

Foam::wordList Foam::demCoupling::demScriptCheck::words
(
    const std::string& line
)
{
    std::string s(line.substr(0, line.find('#')));
    DynamicList<word> found;
    std::size_t pos = 0;
    while (true)
    {
        const std::size_t b = s.find_first_not_of(" \t\r", pos);
        if (b == std::string::npos) break;
        const std::size_t e = s.find_first_of(" \t\r", b);
        found.append(word(s.substr(b, e - b), false));
        if (e == std::string::npos) break;
        pos = e;
    }
    return wordList(std::move(found));
}


void Foam::demCoupling::demScriptCheck::forEachCommand
(
    std::istream& is,
    const std::function<void(const label, const wordList&)>& visit
)
{
    // Join LIGGGHTS continuation lines ('&' at the end) while reading; a
    // command is numbered by its first line
    std::string line, joined;
    label lineNo = 0, firstLine = 1;
    while (std::getline(is, line))
    {
        ++lineNo;
        if (joined.empty())
        {
            firstLine = lineNo;
        }
        const auto amp = line.find_last_not_of(" \t\r");
        if (amp != std::string::npos && line[amp] == '&')
        {
            joined += line.substr(0, amp) + ' ';
            continue;
        }
        joined += line;
        const wordList w(words(joined));
        joined.clear();
        visit(firstLine, w);
    }
}


Foam::fileName Foam::demCoupling::demScriptCheck::includePath
(
    const fileName& path,
    const fileName& caseDir
)
{
    return path.isAbsolute() ? path : caseDir/path;
}


std::string Foam::demCoupling::demScriptCheck::whereIs
(
    const std::string& command,
    const fileName& script,
    const fileName& caseDir,
    const label depth
)
{
    std::ifstream is(script.c_str());
    const wordList target(words(command));
    if (!is.good() || target.empty() || depth > 16)
    {
        return std::string();
    }
    std::string found;
    forEachCommand
    (
        is,
        [&](const label lineNo, const wordList& w)
        {
            if (!found.empty())
            {
                return;
            }
            if (w == target)
            {
                fileName shown(script);
                if (shown.compare(0, caseDir.size() + 1, caseDir + "/") == 0)
                {
                    shown = shown.substr(caseDir.size() + 1);
                }
                found = shown + " line " + std::to_string(lineNo);
            }
            else if
            (
                w.size() == 2 && w[0] == "include"
             && w[1].find('$') == std::string::npos
            )
            {
                found = whereIs
                (
                    command, includePath(w[1], caseDir), caseDir, depth + 1
                );
            }
        }
    );
    return found;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

void Foam::demCoupling::demScriptCheck::scan
(
    const fileName& script,
    const label depth,
    const fileName& parent,
    const label parentLine
)
{
    std::ifstream is(script.c_str());
    if (!is.good())
    {
        FatalIOErrorInFunction(dict_)
            << "Cannot open the DEM script " << script << nl;
        if (parent.empty())
        {
            FatalIOError
                << "    (keyword demScript, or demRestartScript when"
                << " restarting; relative to the case directory)";
        }
        else
        {
            FatalIOError
                << "    (include on line " << parentLine << " of " << parent
                << "; paths are relative to the case directory)";
        }
        FatalIOError << exit(FatalIOError);
    }
    if (depth > 16)
    {
        FatalIOErrorInFunction(dict_)
            << "DEM script " << script << ": 'include' nested deeper than 16"
            << " levels (a file that includes itself?)"
            << exit(FatalIOError);
    }

    forEachCommand
    (
        is,
        [&](const label lineNo, const wordList& w)
        {
            if (w.size() == 2 && w[0] == "include")
            {
                // A path with LIGGGHTS variables (${dir}/in.x) is left to
                // the check on the live instance
                if (w[1].find('$') == std::string::npos)
                {
                    scan(includePath(w[1], caseDir_), depth + 1, script, lineNo);
                }
                return;
            }
            if (w.size() < 4 || w[0] != "fix")
            {
                return;
            }
            if (w[3] == "couple/cfd")
            {
                haveCouple_ = true;
                // fix <id> <group> couple/cfd couple_every <N> mpi
                if
                (
                    w.size() < 7
                 || (w[4] != "couple_every" && w[4] != "every")
                 || w[6] != "mpi"
                )
                {
                    FatalIOErrorInFunction(dict_)
                        << "DEM script " << script << " line " << lineNo
                        << ": expected" << nl
                        << "    fix <id> all couple/cfd couple_every <N> mpi"
                        << nl << "(interDemFoam exchanges data through MPI"
                        << " in one process; the 'file' coupling is not"
                        << " supported)" << exit(FatalIOError);
                }
                if (!readLabel(w[5], coupleEvery_) || coupleEvery_ < 1)
                {
                    FatalIOErrorInFunction(dict_)
                        << "DEM script " << script << " line " << lineNo
                        << ": couple_every must be a whole number >= 1"
                        << " written out (not a variable), found '" << w[5]
                        << "'" << exit(FatalIOError);
                }
            }
            else if
            (
                w[3] == "couple/cfd/force" || w[3] == "couple/cfd/dragforce"
             || w[3] == "couple/cfd/force/implicit"
            )
            {
                haveForce_ = true;
            }
            else if (w[3].compare(0, 7, "insert/") == 0)
            {
                inserts_ = true;
            }
        }
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCoupling::demScriptCheck::demScriptCheck
(
    const fileName& script,
    const fileName& caseDir,
    const dictionary& dict
)
:
    dict_(dict),
    caseDir_(caseDir),
    coupleEvery_(-1),
    haveCouple_(false),
    haveForce_(false),
    inserts_(false)
{
    scan(script, 0, fileName::null, 0);

    if (!haveCouple_ || !haveForce_)
    {
        FatalIOErrorInFunction(dict_)
            << "The DEM script " << script << " lacks the coupling fix"
            << (haveCouple_ ? "" : " 'couple/cfd'")
            << (haveCouple_ || haveForce_ ? "" : " and the fix")
            << (haveForce_ ? "" : " 'couple/cfd/force'") << "." << nl
            << "    It must hold both:" << nl
            << "    fix cfd  all couple/cfd couple_every <N> mpi" << nl
            << "    fix cfd2 all couple/cfd/force" << nl
            << "    with N = deltaT (CFD) / timestep (DEM)."
            << exit(FatalIOError);
    }
}
