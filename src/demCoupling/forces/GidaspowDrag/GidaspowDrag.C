// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "GidaspowDrag.H"
#include "SchillerNaumannDrag.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace demCoupling
{
namespace forceModels
{
    defineTypeNameAndDebug(GidaspowDrag, 0);
    addToRunTimeSelectionTable(forceModel, GidaspowDrag, dictionary);
}
}
}


Foam::demCoupling::forceModels::GidaspowDrag::GidaspowDrag
(
    const dictionary& coeffs
)
:
    dragModel(coeffs)
{}


Foam::scalar Foam::demCoupling::forceModels::GidaspowDrag::CdRe
(
    const scalar Re,
    const scalar eps
) const
{
    // Ergun: beta V_p/(1 - eps) = V_p (150 (1 - eps) mu/(eps d^2)
    // + 1.75 rho |u - v|/d), i.e. (pi mu d/8)(200 (1 - eps) + 7/3 Re)/eps
    return
        eps < ergunLimit
      ? 200*(1 - eps) + 7.0/3.0*Re
      : SchillerNaumannDrag::sphereCdRe(Re);
}


Foam::scalar Foam::demCoupling::forceModels::GidaspowDrag::voidageFunction
(
    const scalar,
    const scalar eps
) const
{
    // Wen & Yu: 3/4 Cd rho eps |u-v|/d V_p eps^-2.65 = Cd Re pi mu d/8 eps^-2.65
    return eps < ergunLimit ? 1/eps : pow(eps, -2.65);
}


// ************************************************************************* //
