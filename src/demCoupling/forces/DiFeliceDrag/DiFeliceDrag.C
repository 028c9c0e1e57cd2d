// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "DiFeliceDrag.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

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
    forceModel(coeffs)
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


Foam::demCoupling::particleForce
Foam::demCoupling::forceModels::DiFeliceDrag::force
(
    const particleFluidState& s
) const
{
    particleForce f;

    const scalar magUr = mag(s.Uf - s.Up);
    const scalar Re = s.eps*s.d*s.rhoF*magUr/s.muF;

    if (Re < ROOTVSMALL)
    {
        // Re -> 0: Cd -> 23.04/Re, so K = 1/2 Cd rho (pi d^2/4) eps^(2-chi)
        // |u-v| tends to the finite 2.88 pi mu d eps^(1-chi), with chi at
        // Re -> 0 (the exponential term vanishes there)
        const scalar chi0 = voidageExponent(ROOTVSMALL, s.eps);
        f.K = 2.88*constant::mathematical::pi*s.muF*s.d
            *pow(s.eps, 1 - chi0);
        return f;
    }

    f.K = 0.5*Cd(Re)*s.rhoF*constant::mathematical::pi/4*sqr(s.d)
        *pow(s.eps, 2 - voidageExponent(Re, s.eps))*magUr;

    return f;
}
