// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
/*---------------------------------------------------------------------------*\
    Unit tests of libdemCoupling (GoogleTest).

        demCouplingTests [gtest options] -case <meshCase>

    The case must hold a mesh (blockMesh of tests/unit/meshCase).
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
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

    return RUN_ALL_TESTS();
}
