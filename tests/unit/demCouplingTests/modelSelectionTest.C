// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
// Run-time selection: a misspelled model name is an error that names the
// keyword and lists the valid models; bad coefficients are rejected.

#include <gtest/gtest.h>
#include "testMain.H"
#include "voidFractionModel.H"
#include "forceModel.H"
#include "OStringStream.H"

using namespace Foam;
using namespace Foam::demCoupling;
using testing_demCoupling::errorMessage;


TEST(modelSelection, UnknownVoidFractionListsValidModels)
{
    dictionary dict;
    dict.add("voidFraction", "centr");
    dict.add("minVoidFraction", 0.2);

    const std::string msg = errorMessage
    (
        [&]{ voidFractionModel::New(dict, testing_demCoupling::mesh()); }
    );
    EXPECT_NE(msg.find("centr"), std::string::npos) << msg;
    EXPECT_NE(msg.find("voidFraction"), std::string::npos) << msg;
    EXPECT_NE(msg.find("centre"), std::string::npos) << msg;
}


TEST(modelSelection, UnknownForceListsValidModels)
{
    dictionary dict;
    dict.add("forces", wordList({"DiFeliceDrag", "DiFelliceDrag"}));

    const std::string msg =
        errorMessage([&]{ forceModel::NewList(dict); });
    EXPECT_NE(msg.find("DiFelliceDrag"), std::string::npos) << msg;
    EXPECT_NE(msg.find("DiFeliceDrag"), std::string::npos) << msg;
}


TEST(modelSelection, ForceListedTwiceIsAnError)
{
    dictionary dict;
    dict.add("forces", wordList({"DiFeliceDrag", "DiFeliceDrag"}));
    const std::string msg =
        errorMessage([&]{ forceModel::NewList(dict); });
    EXPECT_NE(msg.find("twice"), std::string::npos) << msg;
}


TEST(modelSelection, MinVoidFractionOutOfRange)
{
    for (const scalar bad : {0.0, 1.0, -0.1, 1.5})
    {
        dictionary dict;
        dict.add("voidFraction", "centre");
        dict.add("minVoidFraction", bad);
        const std::string msg = errorMessage
        (
            [&]{ voidFractionModel::New(dict, testing_demCoupling::mesh()); }
        );
        EXPECT_NE(msg.find("minVoidFraction"), std::string::npos)
            << "value " << bad << ": " << msg;
        EXPECT_NE(msg.find("> 0 and < 1"), std::string::npos)
            << "the allowed range is not named: " << msg;
    }
}


TEST(modelSelection, ForcesKeywordMissing)
{
    dictionary dict;
    const std::string msg =
        errorMessage([&]{ forceModel::NewList(dict); });
    EXPECT_NE(msg.find("forces"), std::string::npos) << msg;
}
