// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "DiFeliceDrag.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace demCoupling
{
namespace forceModels
{
    defineTypeNameAndDebug(DiFeliceDrag, 0);
    addToRunTimeSelectionTable(forceModel, DiFeliceDrag, dictionary);
}
}
}


Foam::demCoupling::forceModels::DiFeliceDrag::DiFeliceDrag
(
    const dictionary& coeffs
)
:
    dragModel(coeffs)
{}


Foam::scalar Foam::demCoupling::forceModels::DiFeliceDrag::Cd(const scalar Re)
{
    return sqr(0.63 + 4.8/sqrt(Re));
}


Foam::scalar Foam::demCoupling::forceModels::DiFeliceDrag::chi(const scalar Re)
{
    return 3.7 - 0.65*exp(-0.5*sqr(1.5 - log10(Re)));
}


Foam::scalar Foam::demCoupling::forceModels::DiFeliceDrag::voidageExponent
(
    const scalar Re,
    const scalar
) const
{
    return chi(Re);
}


Foam::scalar Foam::demCoupling::forceModels::DiFeliceDrag::CdRe
(
    const scalar Re,
    const scalar
) const
{
    return sqr(0.63*sqrt(Re) + 4.8);
}


Foam::scalar Foam::demCoupling::forceModels::DiFeliceDrag::voidageFunction
(
    const scalar Re,
    const scalar eps
) const
{
    // chi takes log10(Re): at Re -> 0 its Gaussian term vanishes, so chi at
    // ROOTVSMALL is its limit without a log of zero
    return pow(eps, 1 - voidageExponent(max(Re, ROOTVSMALL), eps));
}


// ************************************************************************* //
