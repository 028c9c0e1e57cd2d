// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
// The one input check (core/inputCheck) and the keywords the rooms declare
// (core/couplingKeywords): an unknown keyword names the nearest allowed
// one and all of them; a value out of its rule names the keyword, the
// value and the rule; a wrong word of an Enum lists the allowed words; the
// allowed keywords of couplingProperties are those the rooms read.

#include <gtest/gtest.h>
#include "testMain.H"
#include "inputCheck.H"
#include "couplingKeywords.H"
#include "couplingControls.H"

using namespace Foam;
using namespace Foam::demCoupling;
using testing_demCoupling::errorMessage;


TEST(inputCheck, SentenceJoinsWords)
{
    EXPECT_EQ(inputCheck::sentence(wordList()), "");
    EXPECT_EQ(inputCheck::sentence(wordList({"a"})), "a");
    EXPECT_EQ(inputCheck::sentence(wordList({"a", "b"})), "a and b");
    EXPECT_EQ(inputCheck::sentence(wordList({"a", "b", "c"})), "a, b and c");
}


TEST(inputCheck, NearestIsATypoOnly)
{
    const wordList allowed({"minVoidFraction", "demDrag", "forces"});
    EXPECT_EQ(inputCheck::nearest("minVoidfraction", allowed), "minVoidFraction");
    EXPECT_EQ(inputCheck::nearest("demdrag", allowed), "demDrag");
    EXPECT_EQ(inputCheck::nearest("force", allowed), "forces");
    // nothing close: no guess
    EXPECT_EQ(inputCheck::nearest("turbulence", allowed), "");
}


TEST(inputCheck, UnknownKeywordNamesNearestAndAll)
{
    dictionary dict;
    dict.add("intensity", 0.5);
    dict.add("eddytime", 0.1);
    const std::string msg = errorMessage
    (
        [&]{ inputCheck::keywords(dict, {"intensity", "eddyTime", "seed"}); }
    );
    EXPECT_NE(msg.find("Unknown keyword 'eddytime'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("Did you mean 'eddyTime'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("intensity, eddyTime and seed"), std::string::npos) << msg;

    // every keyword known: no error
    dictionary good;
    good.add("intensity", 0.5);
    good.add("eddyTime", 0.1);
    EXPECT_EQ(errorMessage([&]{ inputCheck::keywords(good, {"intensity", "eddyTime"}); }), "");
}


TEST(inputCheck, RuleNamesKeywordValueAndRule)
{
    dictionary dict;
    dict.add("bandwidth", -0.003);
    const std::string msg = errorMessage
    (
        [&]{ inputCheck::get<scalar>(dict, "bandwidth", &inputCheck::positive, "> 0 (m)"); }
    );
    EXPECT_NE(msg.find("bandwidth -0.003"), std::string::npos) << msg;
    EXPECT_NE(msg.find("must be > 0 (m)"), std::string::npos) << msg;

    dictionary ok;
    ok.add("bandwidth", 0.003);
    EXPECT_EQ
    (
        inputCheck::get<scalar>(ok, "bandwidth", &inputCheck::positive, "> 0"),
        0.003
    );
    // a default only where the key is absent, and checked too
    EXPECT_EQ
    (
        inputCheck::getOrDefault<scalar>(ok, "other", 2.0, &inputCheck::positive, "> 0"),
        2.0
    );
}


TEST(inputCheck, EnumWordListsAllowed)
{
    dictionary dict;
    dict.add("demDrag", "implicitt");
    const std::string msg = errorMessage
    (
        [&]
        {
            inputCheck::selectOrDefault
            (
                dict, "demDrag", couplingControls::demDragPolicyNames,
                couplingControls::demDragPolicy::implicitDrag,
                "implicit and explicit"
            );
        }
    );
    EXPECT_NE(msg.find("demDrag 'implicitt'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("allowed are implicit and explicit"), std::string::npos) << msg;
    EXPECT_NE(msg.find("Did you mean 'implicit'"), std::string::npos) << msg;

    // absent: the default; present and right: its value
    dictionary none;
    EXPECT_TRUE
    (
        inputCheck::selectOrDefault
        (
            none, "demDrag", couplingControls::demDragPolicyNames,
            couplingControls::demDragPolicy::implicitDrag, "-"
        ) == couplingControls::demDragPolicy::implicitDrag
    );
    dictionary expl;
    expl.add("demDrag", "explicit");
    EXPECT_TRUE
    (
        inputCheck::selectOrDefault
        (
            expl, "demDrag", couplingControls::demDragPolicyNames,
            couplingControls::demDragPolicy::implicitDrag, "-"
        ) == couplingControls::demDragPolicy::explicitForce
    );
}


TEST(couplingKeywords, EveryRoomDeclaresWhatItReads)
{
    // One keyword of each room that reads couplingProperties, and the
    // <model>Coeffs of each model family
    const wordList allowed(couplingKeywords::allowed());
    for
    (
        const word key :
        {
            "demScript", "demRestartScript",        // restart/demStartState
            "voidFraction", "minVoidFraction",      // voidFraction/
            "forces",                               // forces/
            "momentumCoupling",                     // momentumCoupling/
            "exchange",                             // exchange/
            "outsideParticles", "demDrag",          // controls/
            "fluidVelocity", "velocityFluctuation", // fluid/
            "virtualSphereCoeffs", "diffusionCoeffs",
            "DiFeliceDragCoeffs", "SaffmanLiftCoeffs"
        }
    )
    {
        EXPECT_TRUE(allowed.found(key))
            << key << " not in " << inputCheck::sentence(allowed);
    }
    // and nothing else: a keyword no room reads is not allowed
    EXPECT_FALSE(allowed.found("turbulence"));
    // sorted, each once
    for (label i = 1; i < allowed.size(); ++i)
    {
        EXPECT_LT(allowed[i - 1], allowed[i]);
    }
}
