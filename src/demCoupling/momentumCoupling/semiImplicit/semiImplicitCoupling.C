// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "semiImplicitCoupling.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace demCoupling
{
namespace momentumCouplingModels
{
    defineTypeNameAndDebug(semiImplicitCoupling, 0);
    addToRunTimeSelectionTable
    (
        momentumCouplingModel,
        semiImplicitCoupling,
        dictionary
    );
}
}
}


Foam::demCoupling::momentumCouplingModels::semiImplicitCoupling::
semiImplicitCoupling
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    momentumCouplingModel(dict, mesh)
{}


void Foam::demCoupling::momentumCouplingModels::semiImplicitCoupling::assemble
(
    const particleData& particles,
    const voidFractionModel& voidFraction,
    const scalarList& K,
    const List<vector>&,
    const List<vector>& Up,
    const List<vector>& Fexplicit,
    volScalarField& Ksl,
    volVectorField& Us,
    volVectorField& fExplicit
) const
{
    List<vector> Kv(particles.size());
    forAll(Kv, i)
    {
        Kv[i] = K[i]*Up[i];
    }

    Ksl.primitiveFieldRef() = voidFraction.spread(K);
    fExplicit.primitiveFieldRef() = -voidFraction.spread(Fexplicit);

    // Drag-weighted particle velocity; volume-weighted where no drag
    const vectorField KvCell(voidFraction.spread(Kv));
    const vectorField UsVolume(volumeWeightedVelocity(particles, voidFraction));
    forAll(Us, c)
    {
        Us[c] = Ksl[c] > SMALL ? KvCell[c]/Ksl[c] : UsVolume[c];
    }

    Ksl.correctBoundaryConditions();
    Us.correctBoundaryConditions();
    fExplicit.correctBoundaryConditions();
}


// ************************************************************************* //
