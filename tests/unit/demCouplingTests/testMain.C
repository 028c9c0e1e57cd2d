// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
/*---------------------------------------------------------------------------*\
    Unit tests of libdemCoupling (GoogleTest).

        demCouplingTests [gtest options] -case <meshCase>

    The case must hold a mesh (blockMesh of tests/unit/meshCase).
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include <cstdlib>
#include "argList.H"
#include "Time.H"
#include "fvMesh.H"
#include "testMain.H"

namespace
{
    Foam::autoPtr<Foam::fvMesh> meshPtr;
}

const Foam::fvMesh& testing_demCoupling::mesh()
{
    return *meshPtr;
}


// The harness's own negative control (ctest unit.failureReported): with
// DEMCOUPLING_TESTS_FAIL set this test fails, and the binary must exit
// non-zero
TEST(harness, FailsWhenAsked)
{
    EXPECT_EQ(std::getenv("DEMCOUPLING_TESTS_FAIL"), nullptr)
        << "DEMCOUPLING_TESTS_FAIL is set: this failure is on purpose";
}


int main(int argc, char *argv[])
{
    ::testing::InitGoogleTest(&argc, argv);

    Foam::argList::noBanner();
    Foam::argList::noParallel();
    Foam::argList args(argc, argv);

    Foam::Time runTime(Foam::Time::controlDictName, args);
    meshPtr.reset
    (
        new Foam::fvMesh
        (
            Foam::IOobject
            (
                Foam::fvMesh::defaultRegion,
                runTime.timeName(),
                runTime,
                Foam::IOobject::MUST_READ
            )
        )
    );

    // Errors become exceptions that the negative tests can catch
    Foam::FatalError.throwExceptions();
    Foam::FatalIOError.throwExceptions();

    const int result = RUN_ALL_TESTS();

    // The mesh before the Time it refers to
    meshPtr.clear();

    // Not "return result": argList's destructor ends every OpenFOAM
    // application with UPstream::exit(0), which turned failed tests into
    // exit status 0 (ctest saw a pass). Leave with GoogleTest's own status,
    // before args goes out of scope.
    std::exit(result);
}
