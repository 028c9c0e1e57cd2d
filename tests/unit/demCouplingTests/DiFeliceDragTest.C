// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
// Di Felice drag (seed eq. 14, Cd squared, voidage eps^(2-chi)) against
// values computed by hand (independent Python evaluation of the formulas,
// 12 digits) and against the seed's single-particle benchmark.

#include <gtest/gtest.h>
#include "DiFeliceDrag.H"
#include "mathematicalConstants.H"

using namespace Foam;
using namespace Foam::demCoupling;

namespace
{
particleFluidState state
(
    scalar d, scalar rhoF, scalar muF, scalar eps, scalar slip
)
{
    particleFluidState s;
    s.d = d;
    s.rhoF = rhoF;
    s.muF = muF;
    s.eps = eps;
    s.Uf = vector(0, 0, slip);   // fluid moves up past a resting particle
    return s;
}

scalar dragMagnitude(const particleFluidState& s)
{
    forceModels::DiFeliceDrag drag{dictionary()};
    return mag(drag.force(s).total(s));
}
}


TEST(DiFeliceDrag, CdAndChi)
{
    using forceModels::DiFeliceDrag;
    // Re = 134 (the seed's terminal state)
    EXPECT_NEAR(DiFeliceDrag::Cd(134), 1.0913079223, 1e-9);
    EXPECT_NEAR(DiFeliceDrag::chi(134), 3.16602866976, 1e-10);
    // Re = 900: 4.8/30 = 0.16, Cd = 0.79^2
    EXPECT_NEAR(DiFeliceDrag::Cd(900), 0.6241, 1e-12);
    // chi is smallest (3.05) at log10(Re) = 1.5
    EXPECT_NEAR(DiFeliceDrag::chi(std::pow(10.0, 1.5)), 3.05, 1e-12);
}


TEST(DiFeliceDrag, DiluteModerateRe)
{
    // water, 1 mm, eps = 1, slip 0.134 m/s: Re = 134
    EXPECT_NEAR
    (
        dragMagnitude(state(1e-3, 1000, 1e-3, 1, 0.134)),
        7.69514469364e-06, 1e-6*7.69514469364e-06
    );
}


TEST(DiFeliceDrag, DenseLowRe)
{
    // dense bed eps = 0.4, 2 mm, slip 0.01 m/s: Re = 8
    EXPECT_NEAR
    (
        dragMagnitude(state(2e-3, 1000, 1e-3, 0.4, 0.01)),
        2.45346537943e-06, 1e-6*2.45346537943e-06
    );
}


TEST(DiFeliceDrag, AirHighRe)
{
    // air, 5 mm, eps = 0.9, slip 2 m/s: Re = 900
    EXPECT_NEAR
    (
        dragMagnitude(state(5e-3, 1, 1e-5, 0.9, 2)),
        2.86266593005e-05, 1e-6*2.86266593005e-05
    );
}


TEST(DiFeliceDrag, DirectionOpposesSlip)
{
    particleFluidState s(state(1e-3, 1000, 1e-3, 1, 0.1));
    s.Up = vector(0.2, 0, 0);
    forceModels::DiFeliceDrag drag{dictionary()};
    const vector F = drag.force(s).total(s);
    const vector slip = s.Uf - s.Up;
    EXPECT_NEAR((F/mag(F)) & (slip/mag(slip)), 1.0, 1e-12);
}


TEST(DiFeliceDrag, StokesLimitIsFiniteAndContinuous)
{
    // Re -> 0: K -> 2.88 pi mu d eps^(1 - 3.7)
    forceModels::DiFeliceDrag drag{dictionary()};
    const scalar eps = 0.5, d = 1e-3, mu = 1e-3;
    const scalar Klimit =
        2.88*constant::mathematical::pi*mu*d*std::pow(eps, 1 - 3.7);

    particleFluidState s(state(d, 1000, mu, eps, 0));
    EXPECT_NEAR(drag.force(s).K, Klimit, 1e-12*Klimit);

    s.Uf = vector(0, 0, 1e-12);   // Re = 5e-7
    EXPECT_NEAR(drag.force(s).K, Klimit, 1e-3*Klimit);
}


TEST(DiFeliceDrag, LoneParticleLimit)
{
    // eps -> 1: the voidage factor drops out, F = 1/2 Cd rho A slip^2
    const scalar d = 1e-3, slip = 0.05, rho = 1000, mu = 1e-3;
    const scalar Re = d*rho*slip/mu;
    const scalar F1 = 0.5*forceModels::DiFeliceDrag::Cd(Re)*rho
        *constant::mathematical::pi/4*d*d*slip*slip;
    EXPECT_NEAR(dragMagnitude(state(d, rho, mu, 1, slip)), F1, 1e-12*F1);
}


TEST(DiFeliceDrag, SeedTerminalVelocity)
{
    // Seed Table 1: 1 mm, 2500 kg/m3 in water; drag balances submerged
    // weight at 0.134 m/s (seed Fig. 2). Bisection on the slip.
    const scalar d = 1e-3, rhoP = 2500, rhoF = 1000, mu = 1e-3, g = 9.81;
    const scalar W = (rhoP - rhoF)*g*constant::mathematical::pi/6*d*d*d;

    scalar lo = 1e-4, hi = 1;
    for (int i = 0; i < 100; ++i)
    {
        const scalar mid = 0.5*(lo + hi);
        (dragMagnitude(state(d, rhoF, mu, 1, mid)) < W ? lo : hi) = mid;
    }
    EXPECT_NEAR(lo, 0.134, 0.02*0.134);
}
