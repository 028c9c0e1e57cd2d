// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "GidaspowDrag.H"
#include "SchillerNaumannDrag.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

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
    forceModel(coeffs)
{}


Foam::demCoupling::particleForce
Foam::demCoupling::forceModels::GidaspowDrag::force
(
    const particleFluidState& s
) const
{
    using constant::mathematical::pi;

    const scalar Vp = pi/6*pow3(s.d);
    const scalar magUr = mag(s.Uf - s.Up);

    particleForce f;

    if (s.eps < ergunLimit)
    {
        // beta V_p/(1 - eps) with the (1 - eps) cancelled
        f.K = Vp
           *(
                150*(1 - s.eps)*s.muF/(s.eps*sqr(s.d))
              + 1.75*s.rhoF*magUr/s.d
            );
    }
    else
    {
        // 3/4 Cd rho |u-v|/d V_p eps^-1.65 with Cd of Re = eps d rho |u-v|/mu:
        // Cd Re pi mu d/8 eps^-2.65, finite as Re -> 0
        const scalar Re = s.eps*s.d*s.rhoF*magUr/s.muF;
        f.K = SchillerNaumannDrag::CdRe(Re)*pi*s.muF*s.d/8*pow(s.eps, -2.65);
    }

    return f;
}


// ************************************************************************* //
