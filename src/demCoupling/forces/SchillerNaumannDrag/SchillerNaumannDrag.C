// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "SchillerNaumannDrag.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace demCoupling
{
namespace forceModels
{
    defineTypeNameAndDebug(SchillerNaumannDrag, 0);
    addToRunTimeSelectionTable(forceModel, SchillerNaumannDrag, dictionary);
}
}
}


Foam::demCoupling::forceModels::SchillerNaumannDrag::SchillerNaumannDrag
(
    const dictionary& coeffs
)
:
    forceModel(coeffs)
{}


Foam::scalar Foam::demCoupling::forceModels::SchillerNaumannDrag::CdRe
(
    const scalar Re
)
{
    return Re < 1000 ? 24*(1 + 0.15*pow(Re, 0.687)) : 0.44*Re;
}


Foam::demCoupling::particleForce
Foam::demCoupling::forceModels::SchillerNaumannDrag::force
(
    const particleFluidState& s
) const
{
    using constant::mathematical::pi;

    const scalar magUr = mag(s.Uf - s.Up);
    const scalar Re = s.d*s.rhoF*magUr/s.muF;

    // K = 1/2 Cd rho (pi d^2/4) |u - v| = Cd Re pi mu d/8: finite at Re = 0
    particleForce f;
    f.K = CdRe(Re)*pi*s.muF*s.d/8;
    return f;
}


// ************************************************************************* //
