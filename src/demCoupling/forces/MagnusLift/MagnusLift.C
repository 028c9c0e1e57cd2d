// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "MagnusLift.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace demCoupling
{
namespace forceModels
{
    defineTypeNameAndDebug(MagnusLift, 0);
    addToRunTimeSelectionTable(forceModel, MagnusLift, dictionary);
}
}
}


Foam::demCoupling::forceModels::MagnusLift::MagnusLift
(
    const dictionary& coeffs
)
:
    forceModel(coeffs)
{}


Foam::demCoupling::particleForce
Foam::demCoupling::forceModels::MagnusLift::force
(
    const particleFluidState& s
) const
{
    particleForce f;
    f.explicitForce = constant::mathematical::pi/8*pow3(s.d)*s.rhoF
        *((0.5*s.vorticity - s.omega) ^ (s.Uf - s.Up));
    return f;
}


// ************************************************************************* //
