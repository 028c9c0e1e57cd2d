// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "WibergSmithLift.H"
#include "inputCheck.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace demCoupling
{
namespace forceModels
{
    defineTypeNameAndDebug(WibergSmithLift, 0);
    addToRunTimeSelectionTable(forceModel, WibergSmithLift, dictionary);
}
}
}


namespace
{

// C_L from WibergSmithLiftCoeffs (required: lift on bed grains is debated)
Foam::scalar readLiftCoefficient(const Foam::dictionary& coeffs)
{
    using namespace Foam;
    demCoupling::inputCheck::keywords(coeffs, {"liftCoefficient"});
    if (!coeffs.found("liftCoefficient"))
    {
        FatalIOErrorInFunction(coeffs)
            << "WibergSmithLift needs liftCoefficient in " << coeffs.name()
            << " (the lift coefficient C_L, between 0 and 2; Wiberg & Smith"
            << " 1985 use 0.2): WibergSmithLiftCoeffs { liftCoefficient"
            << " 0.2; }" << exit(FatalIOError);
    }
    return demCoupling::inputCheck::get<scalar>
    (
        coeffs, "liftCoefficient",
        [](const scalar c) { return c >= 0 && c <= 2; },
        "between 0 and 2 (the lift coefficient C_L; Wiberg & Smith 1985"
        " use 0.2)"
    );
}

} // End anonymous namespace


Foam::demCoupling::forceModels::WibergSmithLift::WibergSmithLift
(
    const dictionary& coeffs
)
:
    forceModel(coeffs),
    liftCoefficient_(readLiftCoefficient(coeffs))
{}


Foam::demCoupling::particleForce
Foam::demCoupling::forceModels::WibergSmithLift::force
(
    const particleFluidState& s
) const
{
    // The relative velocities over the top and under the bottom, across
    // the vertical
    vector top(s.UfTop - s.Up);
    top -= (top & s.up)*s.up;
    vector bottom(s.UfBottom - s.Up);
    bottom -= (bottom & s.up)*s.up;

    particleForce f;
    f.explicitForce = 0.5*liftCoefficient_*s.rhoF
        *constant::mathematical::pi/4*sqr(s.d)
        *(magSqr(top) - magSqr(bottom))*s.up;
    return f;
}


// ************************************************************************* //
