// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "explicitCoupling.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace demCoupling
{
namespace momentumCouplingModels
{
    defineTypeNameAndDebug(explicitCoupling, 0);
    addToRunTimeSelectionTable
    (
        momentumCouplingModel,
        explicitCoupling,
        dictionary
    );
}
}
}


Foam::demCoupling::momentumCouplingModels::explicitCoupling::explicitCoupling
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    momentumCouplingModel(dict, mesh)
{}


void Foam::demCoupling::momentumCouplingModels::explicitCoupling::assemble
(
    const particleData& particles,
    const voidFractionModel& voidFraction,
    const scalarList& K,
    const List<vector>& Uf,
    const List<vector>& Up,
    const List<vector>& Fexplicit,
    volScalarField& Ksl,
    volVectorField& Us,
    volVectorField& fExplicit
) const
{
    List<vector> F(particles.size());
    forAll(F, i)
    {
        F[i] = K[i]*(Uf[i] - Up[i]) + Fexplicit[i];
    }

    Ksl.primitiveFieldRef() = 0;
    fExplicit.primitiveFieldRef() = -voidFraction.spread(F);

    // Volume-weighted particle velocity (for post-processing)
    Us.primitiveFieldRef() = volumeWeightedVelocity(particles, voidFraction);

    Ksl.correctBoundaryConditions();
    Us.correctBoundaryConditions();
    fExplicit.correctBoundaryConditions();
}


// ************************************************************************* //
