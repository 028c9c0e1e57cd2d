// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "dragModel.H"
#include "mathematicalConstants.H"


Foam::demCoupling::dragModel::dragModel(const dictionary& coeffs)
:
    forceModel(coeffs)
{}


Foam::scalar Foam::demCoupling::dragModel::Reynolds
(
    const particleFluidState& s,
    const scalar magUr
) const
{
    return s.eps*s.d*s.rhoF*magUr/s.muF;
}


Foam::demCoupling::particleForce
Foam::demCoupling::dragModel::force(const particleFluidState& s) const
{
    const scalar Re = Reynolds(s, mag(s.Uf - s.Up));

    particleForce f;
    f.K = CdRe(Re, s.eps)*constant::mathematical::pi*s.muF*s.d/8
        *voidageFunction(Re, s.eps);
    return f;
}


// ************************************************************************* //
