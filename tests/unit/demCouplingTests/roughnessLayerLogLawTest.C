// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
// The fluid velocity of a grain with the flow between the bed's crests
// (fluidVelocity roughnessLayer, roughnessLayerLogLaw.H) against closed
// forms and an independent integral. Host cell [0.04, 0.06], a quarter
// full over a full cell: zero plane z_e = 0.045, the cell above's centre
// z_a = 0.07; D = 0.02 m, crests 0.25 D above z_e (z_c = 0.05), troughs
// 1 D below the crests (z_t = 0.03), k_s = 2.9 D (z0 = 1.933 mm):
// - a grain much smaller than z0 sees, along U_a, the log law over D's z0
//   above the crests (not its own diameter's: bedSurfaceLogLaw's 2.9 d/30
//   would give 1.42 times more at z = 0.055), u(z_c) (z - z_t)/(z_c - z_t)
//   between the troughs and the crests (0.75 of u(z_c) at the zero plane,
//   where bedSurfaceLogLaw gives zero) and its host cell's velocity below
//   the troughs;
// - a 10 mm grain with its top at the crests, one in a pocket wholly
//   below the zero plane (a fine grain between 20 mm grains), a 20 mm
//   grain reaching 5 mm above the crests and one centred at the troughs
//   see the drag-equivalent velocity sqrt(int u^2 w dz / A) of the
//   profile, in quadrature with the host velocity's sheltered share: the
//   model's 24-point quadrature in angle against a 20000-interval Simpson
//   integral in height, to 2e-3 of it (the profile's kink at the crests
//   costs the midpoint rule 6.4e-4 on the 20 mm grain across them; the
//   other three agree within 1e-4);
// - the pocketed 10 mm grain under bedSurfaceLogLaw sees its host cell's
//   velocity alone, under roughnessLayer more than twice that: the layer
//   is what gives it a flow;
// - the host cell and the cell below packed (z_e at the host cell's
//   top, 0.06): with the cell above packed too the grain is under the
//   surface and the layer is off (a 10 mm grain wholly below z_e sees its
//   host cell's velocity exactly, one reaching 3 mm above z_e the log law
//   over D's z0 on that part and the host velocity on the rest, against
//   the Simpson integral within 2e-3); with the surface in the cell above
//   (solid 0.1) the layer runs from z_e = 0.06 (a 10 mm grain wholly
//   below z_e sees its profile, within 2e-3, and more than twice its host
//   velocity);
// - missing or inconsistent coefficients stop with an error naming the
//   keyword, and the sampler refuses the coefficients without the model
//   and the model without them.

#include <gtest/gtest.h>
#include "testMain.H"
#include "roughnessLayerLogLaw.H"
#include "fluidSampler.H"
#include "mathematicalConstants.H"
#include <functional>

using namespace Foam;
using namespace Foam::demCoupling;

namespace
{

const scalar D = 0.02, zE = 0.045, zA = 0.07, zC = 0.05, zT = 0.03;
const scalar z0 = 2.9*D/30;

// The header's log law over D's z0 above the zero plane ze, anchored to
// uA at zA, written out independently
scalar logLawSpeed(const scalar z, const scalar uA, const scalar ze)
{
    return
        z - ze > z0
      ? uA*std::min(std::log((z - ze)/z0)/std::log((zA - ze)/z0), 1.0)
      : 0.0;
}

// The header's profile: that log law above the crests zc, linear down to
// the troughs zt, nothing below them
scalar profile
(
    const scalar z,
    const scalar uA,
    const scalar ze = zE,
    const scalar zc = zC,
    const scalar zt = zT
)
{
    if (z >= zc)
    {
        return logLawSpeed(z, uA, ze);
    }
    return z > zt ? logLawSpeed(zc, uA, ze)*(z - zt)/(zc - zt) : 0.0;
}

// sqrt(int over the part of a grain (centre zc, radius r) above bottom of
// u(z)^2 w(z) dz / (pi r^2)), by Simpson's rule in height
scalar dragEquivalent
(
    const scalar zc,
    const scalar r,
    const scalar bottom,
    const std::function<scalar(scalar)>& u
)
{
    const scalar a = std::max(zc - r, bottom);
    const scalar b = zc + r;
    const label n = 20000;
    const scalar h = (b - a)/n;
    scalar sum = 0;
    for (label i = 0; i <= n; ++i)
    {
        const scalar z = a + i*h;
        const scalar w = 2*std::sqrt(std::max(sqr(r) - sqr(z - zc), 0.0));
        sum += (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2))*sqr(u(z))*w;
    }
    return std::sqrt(sum*h/3/(constant::mathematical::pi*sqr(r)));
}

// That integral of the profile over the troughs zT
scalar dragEquivalent(const scalar zc, const scalar r, const scalar uA)
{
    return dragEquivalent
    (
        zc, r, zT, [uA](const scalar z) { return profile(z, uA); }
    );
}

// The sheltered share of a grain's cross-section below height zb
scalar shelteredShare(const scalar zc, const scalar r, const scalar zb)
{
    const scalar c = std::min(std::max((zc - zb)/r, -1.0), 1.0);
    const scalar phi = std::acos(c);
    const scalar pi = constant::mathematical::pi;
    return std::max(1 - (pi - phi + std::sin(phi)*std::cos(phi))/pi, 0.0);
}

const roughnessLayerLogLaw& model()
{
    static const roughnessLayerLogLaw m(2.9, 0.56, D, 0.25, 1);
    return m;
}

vector velocityOf(const scalar zc, const scalar d, const vector& Ua, const vector& Uhost)
{
    // host [0.04, 0.06] a quarter full over a full cell
    return model().velocity(zc, d, 0.04, 0.06, 0.14, 0.56, Ua, Uhost);
}

} // End anonymous namespace


TEST(roughnessLayerLogLaw, SmallGrainSeesTheLayersProfile)
{
    ASSERT_NEAR(model().zeroPlane(0.04, 0.06, 0.14, 0.56), zE, 1e-14);
    const vector Ua(0.8, 0.6, 0);           // |U_a| = 1
    const vector Uhost(0.1, 0, 0.01);
    const scalar d = 1e-5;
    const scalar uC = std::log(0.25*D/z0)/std::log((zA - zE)/z0);
    // above the crests: the log law over D's z0
    {
        const vector U(velocityOf(0.055, d, Ua, Uhost));
        const scalar expected = std::log(0.01/z0)/std::log((zA - zE)/z0);
        EXPECT_NEAR(mag(U), expected, 1e-3*expected);
        EXPECT_NEAR(U.x()/mag(U), 0.8, 1e-12);
        // bedSurfaceLogLaw, its z0 from the grain's own diameter, gives
        // 1.42 times more here
        const bedSurfaceLogLaw logLaw(2.9, 0.56);
        const vector Ulog
        (
            logLaw.velocity(0.055, d, 0.04, 0.06, 0.14, 0.56, Ua, Uhost)
        );
        EXPECT_GT(mag(Ulog), 1.3*mag(U));
    }
    // at the zero plane: 0.75 of the crests' speed (the log law: zero)
    {
        const vector U(velocityOf(zE, d, Ua, Uhost));
        EXPECT_NEAR(mag(U), 0.75*uC, 1e-3*uC);
        EXPECT_NEAR(U.y()/mag(U), 0.6, 1e-12);
    }
    // half-way down the layer
    {
        const vector U(velocityOf(0.04, d, Ua, Uhost));
        EXPECT_NEAR(mag(U), 0.5*uC, 1e-3*uC);
    }
    // below the troughs: the host cell
    EXPECT_EQ(velocityOf(0.029, d, Ua, Uhost), Uhost);
}


TEST(roughnessLayerLogLaw, GrainsSeeTheDragEquivalentVelocity)
{
    const vector Ua(1.03, 0, 0);
    const vector Uhost(0.05, 0, 0.02);
    // a 10 mm grain with its top at the crests, wholly above the troughs
    {
        const scalar zc = 0.045;
        const vector U(velocityOf(zc, 0.01, Ua, Uhost));
        const scalar expected = dragEquivalent(zc, 0.005, 1.03);
        EXPECT_NEAR(mag(U), expected, 2e-3*expected);
    }
    // a 10 mm grain in a pocket, wholly below the zero plane (top at
    // 0.042) and above the troughs (bottom at 0.032): the layer's flow,
    // where bedSurfaceLogLaw gives it its host cell's velocity alone
    {
        const scalar zc = 0.037;
        const vector U(velocityOf(zc, 0.01, Ua, Uhost));
        const scalar expected = dragEquivalent(zc, 0.005, 1.03);
        EXPECT_NEAR(mag(U), expected, 2e-3*expected);
        EXPECT_NEAR(U.z(), 0, 1e-14);
        const bedSurfaceLogLaw logLaw(2.9, 0.56);
        const vector Ulog
        (
            logLaw.velocity(zc, 0.01, 0.04, 0.06, 0.14, 0.56, Ua, Uhost)
        );
        EXPECT_EQ(Ulog, Uhost);
        EXPECT_GT(mag(U), 2*mag(Uhost));
    }
    // a 20 mm grain centred at the zero plane: bottom at 0.035, above the
    // troughs; top at 0.055, 5 mm above the crests
    {
        const scalar zc = 0.045, r = 0.01;
        const vector U(velocityOf(zc, 2*r, Ua, Uhost));
        const scalar expected = dragEquivalent(zc, r, 1.03);
        EXPECT_NEAR(mag(U), expected, 2e-3*expected);
    }
    // a 20 mm grain centred at the troughs: half sheltered, the host's
    // share in quadrature
    {
        const scalar zc = zT, r = 0.01;
        const vector U(velocityOf(zc, 2*r, Ua, Uhost));
        const scalar exposed = dragEquivalent(zc, r, 1.03);
        const scalar share = shelteredShare(zc, r, zT);
        ASSERT_NEAR(share, 0.5, 1e-12);
        const scalar speed = std::sqrt(sqr(exposed) + share*magSqr(Uhost));
        EXPECT_NEAR(mag(U), speed, 2e-3*speed);
    }
}


TEST(roughnessLayerLogLaw, TheLayerFollowsTheSurface)
{
    const vector Ua(1.03, 0, 0);
    const vector Uhost(0.05, 0, 0.02);
    // host [0.04, 0.06] and the cell below packed: z_e = 0.06
    const scalar zEb = 0.06;
    ASSERT_NEAR(model().zeroPlane(0.04, 0.06, 0.56, 0.56), zEb, 1e-14);
    auto velocityAt = [&](const scalar zc, const scalar solidAbove)
    {
        return model().velocity
        (
            zc, 0.01, 0.04, 0.06, 0.56, 0.56, Ua, Uhost, solidAbove
        );
    };
    // the drag-equivalent speed of a 10 mm grain at zc: u over its part
    // above bottom, the host velocity's share below it
    auto expected = [&]
    (
        const scalar zc,
        const scalar bottom,
        const std::function<scalar(scalar)>& u
    )
    {
        const scalar r = 0.005;
        return std::sqrt
        (
            sqr(dragEquivalent(zc, r, bottom, u))
          + shelteredShare(zc, r, bottom)*magSqr(Uhost)
        );
    };
    auto logLawHere = [&](const scalar z) { return logLawSpeed(z, 1.03, zEb); };
    // the cell above packed too: under the surface, no layer
    {
        EXPECT_EQ(velocityAt(0.05, 0.56), Uhost);
        const scalar zc = 0.058;
        const scalar speed = expected(zc, zEb, logLawHere);
        EXPECT_NEAR(mag(velocityAt(zc, 0.56)), speed, 2e-3*speed);
    }
    // the cell above holding the surface (solid 0.1): the layer from
    // z_e = 0.06, crests at 0.065, troughs at 0.045
    {
        const scalar zCb = 0.065, zTb = 0.045;
        auto layer = [&](const scalar z)
        {
            return profile(z, 1.03, zEb, zCb, zTb);
        };
        const scalar zc = 0.05;
        const scalar speed = expected(zc, zTb, layer);
        const vector U(velocityAt(zc, 0.1));
        EXPECT_NEAR(mag(U), speed, 2e-3*speed);
        EXPECT_GT(mag(U), 2*mag(Uhost));
    }
}


TEST(roughnessLayerLogLaw, BadCoefficientsStop)
{
    auto messageOf = [](const dictionary& dict)
    {
        return testing_demCoupling::errorMessage
        (
            [&]{ roughnessLayerLogLaw model(dict); }
        );
    };
    dictionary none;
    EXPECT_NE
    (
        messageOf(none).find("needs the sub-dictionary roughnessLayerCoeffs"),
        std::string::npos
    );
    dictionary coeffs;
    coeffs.add("roughness", 2.9);
    coeffs.add("bedSolidFraction", 0.56);
    coeffs.add("roughnessDiameter", 0.02);
    coeffs.add("crestAboveZeroPlane", 0.25);
    dictionary dict;
    dict.add("roughnessLayerCoeffs", coeffs);
    // layerDepth missing
    EXPECT_THROW(roughnessLayerLogLaw model(dict), Foam::error);
    dict.subDictPtr("roughnessLayerCoeffs")->add("layerDepth", 1.0);
    const roughnessLayerLogLaw good(dict);
    EXPECT_EQ(good.roughnessDiameter(), 0.02);
    EXPECT_EQ(good.layerDepth(), 1.0);
    // the crests at or below z0 = 2.9/30 D
    dict.subDictPtr("roughnessLayerCoeffs")->set("crestAboveZeroPlane", 0.09);
    EXPECT_NE(messageOf(dict).find("crestAboveZeroPlane"), std::string::npos);
    // the troughs above the zero plane
    dict.subDictPtr("roughnessLayerCoeffs")->set("crestAboveZeroPlane", 0.25);
    dict.subDictPtr("roughnessLayerCoeffs")->set("layerDepth", 0.2);
    EXPECT_NE(messageOf(dict).find("layerDepth"), std::string::npos);
    // the solid fraction outside (0, 1), read by bedSurfaceLogLaw's reader
    dict.subDictPtr("roughnessLayerCoeffs")->set("layerDepth", 1.0);
    dict.subDictPtr("roughnessLayerCoeffs")->set("bedSolidFraction", 1.2);
    const std::string fractionMessage(messageOf(dict));
    EXPECT_NE(fractionMessage.find("bedSolidFraction"), std::string::npos);
    EXPECT_NE(fractionMessage.find("between 0 and 1"), std::string::npos);
    dict.subDictPtr("roughnessLayerCoeffs")->set("bedSolidFraction", 0.56);
    // a misspelt keyword
    dict.subDictPtr("roughnessLayerCoeffs")->add("roughnesDiameter", 0.02);
    EXPECT_NE(messageOf(dict).find("roughnesDiameter"), std::string::npos);
}


TEST(roughnessLayerLogLaw, SamplerRefusesCoefficientsWithoutTheModel)
{
    const fvMesh& mesh = testing_demCoupling::mesh();
    const PtrList<forceModel> forces;
    auto messageOf = [&](const dictionary& dict)
    {
        return testing_demCoupling::errorMessage
        (
            [&]{ fluidSampler sampler(dict, mesh, forces); }
        );
    };
    dictionary stray;
    stray.add("fluidVelocity", "grainTop");
    stray.add("roughnessLayerCoeffs", dictionary());
    EXPECT_NE
    (
        messageOf(stray).find("is read only with fluidVelocity roughnessLayer"),
        std::string::npos
    );
    dictionary missing;
    missing.add("fluidVelocity", "roughnessLayer");
    EXPECT_NE
    (
        messageOf(missing).find("needs the sub-dictionary roughnessLayerCoeffs"),
        std::string::npos
    );
}
