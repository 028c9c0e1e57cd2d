// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "SchillerNaumannDrag.H"
#include "addToRunTimeSelectionTable.H"

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
    dragModel(coeffs)
{}


Foam::scalar Foam::demCoupling::forceModels::SchillerNaumannDrag::sphereCdRe
(
    const scalar Re
)
{
    return Re < 1000 ? 24*(1 + 0.15*pow(Re, 0.687)) : 0.44*Re;
}


Foam::scalar Foam::demCoupling::forceModels::SchillerNaumannDrag::Reynolds
(
    const particleFluidState& s,
    const scalar magUr
) const
{
    return s.d*s.rhoF*magUr/s.muF;
}


Foam::scalar Foam::demCoupling::forceModels::SchillerNaumannDrag::CdRe
(
    const scalar Re,
    const scalar
) const
{
    return sphereCdRe(Re);
}


Foam::scalar
Foam::demCoupling::forceModels::SchillerNaumannDrag::voidageFunction
(
    const scalar,
    const scalar
) const
{
    return 1;
}


// ************************************************************************* //
