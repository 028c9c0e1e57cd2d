// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "RongDrag.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace demCoupling
{
namespace forceModels
{
    defineTypeNameAndDebug(RongDrag, 0);
    addToRunTimeSelectionTable(forceModel, RongDrag, dictionary);
}
}
}


Foam::demCoupling::forceModels::RongDrag::RongDrag(const dictionary& coeffs)
:
    DiFeliceDrag(coeffs)
{}


Foam::scalar Foam::demCoupling::forceModels::RongDrag::voidageExponent
(
    const scalar Re,
    const scalar eps
) const
{
    return 2.65*(eps + 1) - (5.3 - 3.5*eps)*sqr(eps)
        *exp(-0.5*sqr(1.5 - log10(Re)));
}


// ************************************************************************* //
