// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
// The turbulent velocity fluctuations seen by the particles
// (velocityFluctuation.H) against the statistics they are meant to have:
// zero mean, streamwise r.m.s. I |U|, lateral and vertical r.m.s. 1.63/2.30
// and 1.27/2.30 of it (Nezu & Nakagawa 1993) along the directions set by U
// and gravity, one value per eddy, unrelated values in successive eddies,
// and the same value for the same particle and time. With the turbulence
// model as source: the eddy lifetimes of Gosman & Ioannides (crossing) and
// of the energy-carrying eddies' turnover time k/epsilon (turnover),
// against their closed forms; sized by the Reynolds shear stress
// (size shearStress), the near-bed r.m.s. per friction velocity.
//
// Sampling error: over n = 40000 independent draws the mean of a unit
// normal has a standard error of 1/sqrt(n) = 0.005 and its r.m.s. one of
// 1/sqrt(2 n) = 0.0035; the tolerances are about four standard errors.

#include <gtest/gtest.h>
#include "velocityFluctuation.H"

using namespace Foam;
using namespace Foam::demCoupling;

namespace
{

const label n = 40000;

// Mean and r.m.s. of each component of the fluctuation over n particles
void statistics
(
    const velocityFluctuation& model,
    const scalar t,
    const vector& U,
    const vector& up,
    vector& mean,
    vector& rms
)
{
    mean = Zero;
    vector sq(Zero);
    for (label tag = 1; tag <= n; ++tag)
    {
        const vector u(model(tag, t, U, up));
        mean += u;
        sq += cmptMultiply(u, u);
    }
    mean /= n;
    sq /= n;
    rms = vector(Foam::sqrt(sq.x()), Foam::sqrt(sq.y()), Foam::sqrt(sq.z()));
}

} // End anonymous namespace


TEST(velocityFluctuation, HasTheNearBedTurbulenceIntensities)
{
    // Flow along x at 0.5 m/s, gravity along -z: streamwise x, lateral y,
    // vertical z
    const velocityFluctuation model(0.3, 0.04, 7);
    const vector U(0.5, 0, 0);
    vector mean, rms;
    statistics(model, 1.234, U, vector(0, 0, 1), mean, rms);

    const scalar sigma = 0.3*0.5;
    EXPECT_NEAR(rms.x()/sigma, 1, 0.015);
    EXPECT_NEAR(rms.y()/sigma, 1.63/2.30, 0.015);
    EXPECT_NEAR(rms.z()/sigma, 1.27/2.30, 0.015);
    for (direction k = 0; k < 3; ++k)
    {
        EXPECT_LT(mag(mean[k])/sigma, 0.02) << "component " << int(k);
    }
}


TEST(velocityFluctuation, ComponentsAreIndependent)
{
    // Each component its own draw: correlation coefficients between the
    // components below 0.02 (standard error 1/sqrt(n) = 0.005)
    const velocityFluctuation model(0.3, 0.04, 11);
    scalar xy = 0, xz = 0, yz = 0, xx = 0, yy = 0, zz = 0;
    for (label tag = 1; tag <= n; ++tag)
    {
        const vector u(model(tag, 2.5, vector(1, 0, 0), vector(0, 0, 1)));
        xy += u.x()*u.y();
        xz += u.x()*u.z();
        yz += u.y()*u.z();
        xx += sqr(u.x());
        yy += sqr(u.y());
        zz += sqr(u.z());
    }
    EXPECT_LT(mag(xy/Foam::sqrt(xx*yy)), 0.02);
    EXPECT_LT(mag(xz/Foam::sqrt(xx*zz)), 0.02);
    EXPECT_LT(mag(yz/Foam::sqrt(yy*zz)), 0.02);
}


TEST(velocityFluctuation, VerticalFlowStillFluctuatesAcross)
{
    // Flow straight up: no vertical direction normal to it; the two
    // across-flow components still carry their r.m.s., the streamwise one
    // lies along z
    const velocityFluctuation model(0.3, 0.04, 7);
    vector mean, rms;
    statistics(model, 1.0, vector(0, 0, 1), vector(0, 0, 1), mean, rms);
    EXPECT_NEAR(rms.z()/0.3, 1, 0.015);
    const scalar across = Foam::sqrt(sqr(rms.x()) + sqr(rms.y()))/0.3;
    EXPECT_NEAR
    (
        across,
        Foam::sqrt
        (
            sqr(velocityFluctuation::lateralRatio)
          + sqr(velocityFluctuation::verticalRatio)
        ),
        0.015
    );
}


TEST(velocityFluctuation, FollowsTheFlowAndGravity)
{
    // The same flow turned: along y, gravity along -x (up = +x). The
    // streamwise r.m.s. must now be along y, the vertical along x
    const velocityFluctuation model(0.2, 0.04, 7);
    const vector U(0, -2, 0);
    vector mean, rms;
    statistics(model, 3.0, U, vector(1, 0, 0), mean, rms);

    const scalar sigma = 0.2*2;
    EXPECT_NEAR(rms.y()/sigma, 1, 0.015);
    EXPECT_NEAR(rms.x()/sigma, 1.27/2.30, 0.015);
    EXPECT_NEAR(rms.z()/sigma, 1.63/2.30, 0.015);
}


TEST(velocityFluctuation, OneValuePerEddyAndNewOnesUnrelated)
{
    const scalar T = 0.04;
    const velocityFluctuation model(0.3, T, 3);
    const vector U(1, 0, 0);
    const vector up(0, 0, 1);

    // Within one eddy the value holds; the next eddy (T later) is another,
    // with no correlation: r = sum(a b)/sqrt(sum a^2 sum b^2) over the
    // particles, standard error 1/sqrt(n) = 0.005
    label held = 0;
    scalar ab = 0, aa = 0, bb = 0;
    for (label tag = 1; tag <= n; ++tag)
    {
        const scalar t0 = 10.0;
        const int64_t e = model.eddy(tag, t0);
        // a time in the same eddy: the eddy's start plus a fraction of T
        const scalar t1 = t0 + 0.3*T;
        if (model.eddy(tag, t1) == e)
        {
            ++held;
            EXPECT_EQ(model(tag, t0, U, up), model(tag, t1, U, up));
        }
        const scalar a = model(tag, t0, U, up).x();
        const scalar b = model(tag, t0 + T, U, up).x();
        EXPECT_EQ(model.eddy(tag, t0 + T), e + 1);
        ab += a*b;
        aa += a*a;
        bb += b*b;
    }
    // each particle's eddies are shifted by a fraction of T of its own: a
    // time 0.3 T later is in the same eddy for about 70 % of them
    EXPECT_NEAR(scalar(held)/n, 0.7, 0.02);
    EXPECT_LT(mag(ab/Foam::sqrt(aa*bb)), 0.02);
}


TEST(velocityFluctuation, NothingWithoutFlowOrIntensity)
{
    const velocityFluctuation model(0.3, 0.04, 1);
    EXPECT_EQ(model(5, 1.0, vector::zero, vector(0, 0, 1)), vector::zero);
    const velocityFluctuation none(0, 0.04, 1);
    EXPECT_EQ(none(5, 1.0, vector(1, 0, 0), vector(0, 0, 1)), vector::zero);
    // and it scales with |U|: twice the flow, twice the fluctuation
    EXPECT_EQ
    (
        model(5, 1.0, vector(2, 0, 0), vector(0, 0, 1)),
        2*model(5, 1.0, vector(1, 0, 0), vector(0, 0, 1))
    );
}


TEST(velocityFluctuation, SeedsGiveOtherDraws)
{
    const velocityFluctuation a(0.3, 0.04, 1), b(0.3, 0.04, 2);
    label same = 0;
    for (label tag = 1; tag <= 1000; ++tag)
    {
        if (a(tag, 1.0, vector(1, 0, 0), vector(0, 0, 1))
         == b(tag, 1.0, vector(1, 0, 0), vector(0, 0, 1)))
        {
            ++same;
        }
    }
    EXPECT_EQ(same, 0);
}


// The eddy lifetimes against their closed forms, l_e = C_mu^(3/4) k^(3/2)/eps
// with C_mu = 0.09: k = 0.037 m2/s2, eps = 0.15 m2/s3 (the bedload channel's
// bed cell at theta = 0.3, docs/erosion.md), so k/eps = 0.2467 s,
// l_e = 0.1643 k^1.5/eps = 7.80 mm and sqrt(2k/3) = 0.157 m/s.
TEST(velocityFluctuation, EddyLifetimesHaveTheirClosedForms)
{
    const scalar k = 0.037, eps = 0.15;
    const scalar le = Foam::pow(0.09, 0.75)*Foam::pow(k, 1.5)/eps;
    const scalar uTurb = Foam::sqrt(2*k/3);
    const velocityFluctuation crossing
    (
        velocityFluctuation::eddyLifetimeModel::crossing, 1
    );
    const velocityFluctuation turnover
    (
        velocityFluctuation::eddyLifetimeModel::turnover, 1
    );

    // A grain at rest: crossing keeps the eddy's own decay, l_e/sqrt(2k/3)
    // = C_mu^(3/4)/sqrt(2/3) k/eps = 0.2012 k/eps; turnover keeps k/eps
    EXPECT_NEAR(crossing.lifetime(k, eps, 0)/(k/eps), 0.2012, 1e-3);
    EXPECT_NEAR(turnover.lifetime(k, eps, 0), k/eps, 1e-12);

    // A slow grain (slip 0.01 m/s, crossing time 0.78 s > k/eps): the same
    EXPECT_NEAR(crossing.lifetime(k, eps, 0.01), le/uTurb, 1e-12);
    EXPECT_NEAR(turnover.lifetime(k, eps, 0.01), k/eps, 1e-12);

    // A grain at rest under flow at 0.5 m/s (slip faster than sqrt(2k/3)):
    // crossing leaves the eddy as the flow carries it past, in
    // l_e/slip = 15.6 ms; turnover keeps k/eps
    EXPECT_NEAR(crossing.lifetime(k, eps, 0.5), le/0.5, 1e-12);
    EXPECT_NEAR(turnover.lifetime(k, eps, 0.5), k/eps, 1e-12);
}


// The lifetime is what the draws keep: a grain at rest under flow at
// 0.5 m/s keeps its fluctuation for k/eps with turnover, for the crossing
// time l_e/0.5 = 0.063 k/eps with crossing. Over n particles the fraction
// that still sees the same eddy after 0.5 k/eps is 0.5 (turnover: each
// particle's eddies are shifted by a uniform fraction of the lifetime) and
// 0 (crossing). Binomial standard error sqrt(0.25/n) = 0.0025.
TEST(velocityFluctuation, TurnoverEddiesLiveLongerForRestingGrains)
{
    const scalar k = 0.037, eps = 0.15;
    const vector U(0.5, 0, 0), up(0, 0, 1);
    const scalar slip = mag(U);
    const velocityFluctuation crossing
    (
        velocityFluctuation::eddyLifetimeModel::crossing, 4
    );
    const velocityFluctuation turnover
    (
        velocityFluctuation::eddyLifetimeModel::turnover, 4
    );
    const scalar t0 = 20.0, dt = 0.5*k/eps;
    label keptTurnover = 0, keptCrossing = 0;
    scalar sq = 0;
    for (label tag = 1; tag <= n; ++tag)
    {
        const vector a(turnover.turbulent(tag, t0, U, up, k, eps, slip));
        if (a == turnover.turbulent(tag, t0 + dt, U, up, k, eps, slip))
        {
            ++keptTurnover;
        }
        if
        (
            crossing.turbulent(tag, t0, U, up, k, eps, slip)
         == crossing.turbulent(tag, t0 + dt, U, up, k, eps, slip)
        )
        {
            ++keptCrossing;
        }
        sq += sqr(a.x());
    }
    EXPECT_NEAR(scalar(keptTurnover)/n, 0.5, 0.01);
    EXPECT_EQ(keptCrossing, 0);
    // and the lifetime leaves the size alone: streamwise r.m.s. 1.05 sqrt(k)
    EXPECT_NEAR
    (
        Foam::sqrt(sq/n)/(velocityFluctuation::streamwisePerSqrtK
       *Foam::sqrt(k)),
        1,
        0.015
    );
}


// size shearStress: the r.m.s. are Nezu & Nakagawa's near-bed 2.30, 1.63
// and 1.27 times the friction velocity of the local Reynolds shear stress,
// u_t = sqrt(shear), whatever k is (here k = 0.037, whose default size
// would be 1.05 sqrt(k) = 0.20 m/s against 2.30 u_t = 0.46 m/s); no
// stress, no fluctuation. Tolerances as above (four standard errors).
TEST(velocityFluctuation, ShearStressSizeHasNezuNakagawasNearBedValues)
{
    const scalar k = 0.037, eps = 0.15, shear = 0.04;
    const vector U(0.5, 0, 0), up(0, 0, 1);
    const velocityFluctuation model
    (
        velocityFluctuation::eddyLifetimeModel::turnover, 9,
        velocityFluctuation::sizeModel::shearStress
    );
    ASSERT_TRUE(model.sizedByShearStress());
    vector sq(Zero);
    for (label tag = 1; tag <= n; ++tag)
    {
        const vector u(model.turbulent(tag, 3.0, U, up, k, eps, 0.5, shear));
        sq += cmptMultiply(u, u);
    }
    sq /= n;
    const scalar uTau = Foam::sqrt(shear);
    EXPECT_NEAR(Foam::sqrt(sq.x())/uTau, 2.30, 2.30*0.015);
    EXPECT_NEAR(Foam::sqrt(sq.y())/uTau, 1.63, 1.63*0.015);
    EXPECT_NEAR(Foam::sqrt(sq.z())/uTau, 1.27, 1.27*0.015);
    EXPECT_EQ(model.turbulent(5, 3.0, U, up, k, eps, 0.5, 0), vector::zero);
}
