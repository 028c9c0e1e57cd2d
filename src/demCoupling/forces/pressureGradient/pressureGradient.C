// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "pressureGradient.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace demCoupling
{
namespace forceModels
{
    defineTypeNameAndDebug(pressureGradient, 0);
    addToRunTimeSelectionTable(forceModel, pressureGradient, dictionary);
}
}
}


Foam::demCoupling::forceModels::pressureGradient::pressureGradient
(
    const dictionary& coeffs
)
:
    forceModel(coeffs)
{}


Foam::demCoupling::particleForce
Foam::demCoupling::forceModels::pressureGradient::force
(
    const particleFluidState& s
) const
{
    const scalar Vp = constant::mathematical::pi/6.0*pow3(s.d);

    particleForce f;
    f.explicitForce = -Vp*s.gradP;
    return f;
}


// ************************************************************************* //
