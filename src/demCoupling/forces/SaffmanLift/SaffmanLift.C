// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "SaffmanLift.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace demCoupling
{
namespace forceModels
{
    defineTypeNameAndDebug(SaffmanLift, 0);
    addToRunTimeSelectionTable(forceModel, SaffmanLift, dictionary);
}
}
}


Foam::demCoupling::forceModels::SaffmanLift::SaffmanLift
(
    const dictionary& coeffs
)
:
    forceModel(coeffs)
{}


Foam::demCoupling::particleForce
Foam::demCoupling::forceModels::SaffmanLift::force
(
    const particleFluidState& s
) const
{
    particleForce f;

    const scalar magW = mag(s.vorticity);
    if (magW < VSMALL)
    {
        return f;
    }

    f.explicitForce = 1.61*sqr(s.d)*sqrt(s.muF*s.rhoF/magW)
        *((s.Uf - s.Up) ^ s.vorticity);
    return f;
}


// ************************************************************************* //
