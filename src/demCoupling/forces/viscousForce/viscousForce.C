// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "viscousForce.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace demCoupling
{
namespace forceModels
{
    defineTypeNameAndDebug(viscousForce, 0);
    addToRunTimeSelectionTable(forceModel, viscousForce, dictionary);
}
}
}


Foam::demCoupling::forceModels::viscousForce::viscousForce
(
    const dictionary& coeffs
)
:
    forceModel(coeffs)
{}


Foam::demCoupling::particleForce
Foam::demCoupling::forceModels::viscousForce::force
(
    const particleFluidState& s
) const
{
    particleForce f;
    f.explicitForce = constant::mathematical::pi/6*pow3(s.d)*s.divTau;
    return f;
}


// ************************************************************************* //
