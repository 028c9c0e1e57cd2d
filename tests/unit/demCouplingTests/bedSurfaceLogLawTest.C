// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
// The fluid velocity of a grain in a bed's surface from the rough-bed log
// law in its cell (fluidVelocity bedSurfaceLogLaw, bedSurfaceLogLaw.H)
// against closed forms and an independent integral:
// - the zero plane where the solids of the host cell and the cell below,
//   packed at the bed's solid fraction, end (half a cell up in a host
//   cell half full over a full one; half a cell down when the cell below
//   is half full and the host empty; never above the host cell);
// - a grain much smaller than the roughness length's scale sees the log
//   law at its centre, u = |U_a| ln((z - z_e)/z0)/ln((z_a - z_e)/z0),
//   along U_a;
// - a grain of 10 mm wholly above the plane, or half below it, sees the
//   drag-equivalent velocity sqrt(int u^2 w dz / A) of its exposed part,
//   in quadrature with its sheltered share of the host cell's velocity:
//   the model's 24-point quadrature in angle against a 20000-interval
//   Simpson integral in height (the same quantity, computed another way),
//   to 2e-3 of it (the midpoint rule's error on this smooth integrand is
//   below 1e-4; the profile over the grain runs from 0.14 to 0.76 of
//   |U_a|, so 2e-3 separates the r.m.s. from the mean);
// - a grain reaching above the cell above's centre sees no more than
//   |U_a| there (the same Simpson integral of the capped law);
// - a buried grain sees its host cell's velocity, unchanged;
// - the host cell's extent along up on the unit-test mesh;
// - missing or out-of-range coefficients stop with an error, and the
//   sampler refuses the coefficients without the model and the model
//   without them.

#include <gtest/gtest.h>
#include "testMain.H"
#include "bedSurfaceLogLaw.H"
#include "fluidSampler.H"
#include "mathematicalConstants.H"

using namespace Foam;
using namespace Foam::demCoupling;

namespace
{

// The profile of the header, written out independently: z measured from
// the zero plane
scalar logLaw(const scalar z, const scalar z0, const scalar zA, const scalar uA)
{
    return z > z0 ? uA*std::min(std::log(z/z0)/std::log(zA/z0), 1.0) : 0;
}

// sqrt(int over the part of a grain (centre zc, radius r) above zE of
// u(z)^2 w(z) dz / (pi r^2)), w the chord 2 sqrt(r^2 - (z - zc)^2), by
// Simpson's rule in height
scalar dragEquivalent
(
    const scalar zc, const scalar r, const scalar zE, const scalar z0,
    const scalar zA, const scalar uA
)
{
    const scalar a = std::max(zc - r, zE);
    const scalar b = zc + r;
    const label n = 20000;
    const scalar h = (b - a)/n;
    scalar sum = 0;
    for (label i = 0; i <= n; ++i)
    {
        const scalar z = a + i*h;
        const scalar w = 2*std::sqrt(std::max(sqr(r) - sqr(z - zc), 0.0));
        const scalar f = sqr(logLaw(z - zE, z0, zA - zE, uA))*w;
        sum += (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2))*f;
    }
    return std::sqrt(sum*h/3/(constant::mathematical::pi*sqr(r)));
}

} // End anonymous namespace


TEST(bedSurfaceLogLaw, ZeroPlaneIsTheTopOfThePackedSolids)
{
    const bedSurfaceLogLaw model(2.9, 0.56);
    // host cell [0.04, 0.06]
    EXPECT_NEAR(model.zeroPlane(0.04, 0.06, 0.28, 0.56), 0.05, 1e-14);
    EXPECT_NEAR(model.zeroPlane(0.04, 0.06, 0.0, 0.28), 0.03, 1e-14);
    EXPECT_NEAR(model.zeroPlane(0.04, 0.06, 0.14, 0.60), 0.045, 1e-14);
    // a host cell packed denser than phi_b: the plane at its top
    EXPECT_NEAR(model.zeroPlane(0.04, 0.06, 0.7, 0.7), 0.06, 1e-14);
}


TEST(bedSurfaceLogLaw, SmallGrainSeesTheLogLawAtItsCentre)
{
    const bedSurfaceLogLaw model(2.9, 0.56);
    const vector Ua(0.8, 0.6, 0);          // |U_a| = 1
    // host [0.04, 0.06] half full over a full cell: z_e = 0.05, z_a = 0.07
    const scalar d = 1e-4;
    const scalar z0 = 2.9*d/30;
    const scalar zc = 0.052;
    const vector U
    (
        model.velocity(zc, d, 0.04, 0.06, 0.28, 0.56, Ua, vector(0.1, 0, 0))
    );
    const scalar expected = std::log(0.002/z0)/std::log(0.02/z0);
    EXPECT_NEAR(mag(U), expected, 1e-4*expected);
    EXPECT_NEAR(U.x()/mag(U), 0.8, 1e-12);
    EXPECT_NEAR(U.y()/mag(U), 0.6, 1e-12);
}


TEST(bedSurfaceLogLaw, ExposedGrainSeesItsDragEquivalentVelocity)
{
    const bedSurfaceLogLaw model(2.9, 0.56);
    const scalar d = 0.01, r = 0.005, z0 = 2.9*d/30;
    const vector Ua(1.03, 0, 0);
    const vector Uhost(0.35, 0, 0.02);
    // z_e = 0.045 (host 1/4 full over a full cell); z_a = 0.07
    const scalar zE = 0.045, zA = 0.07;
    ASSERT_NEAR(model.zeroPlane(0.04, 0.06, 0.14, 0.56), zE, 1e-14);

    // wholly above the plane: no sheltered part
    {
        const scalar zc = 0.0515;
        const vector U
        (
            model.velocity(zc, d, 0.04, 0.06, 0.14, 0.56, Ua, Uhost)
        );
        const scalar expected = dragEquivalent(zc, r, zE, z0, zA, 1.03);
        EXPECT_NEAR(U.x(), expected, 2e-3*expected);
        EXPECT_NEAR(U.z(), 0, 1e-14);
        // between the profile at the grain's bottom and at its top
        EXPECT_GT(U.x(), logLaw(zc - r - zE, z0, zA - zE, 1.03));
        EXPECT_LT(U.x(), logLaw(zc + r - zE, z0, zA - zE, 1.03));
    }
    // centred on the plane: half sheltered, the host's share in quadrature
    {
        const scalar zc = zE;
        const vector U
        (
            model.velocity(zc, d, 0.04, 0.06, 0.14, 0.56, Ua, Uhost)
        );
        const scalar exposed = dragEquivalent(zc, r, zE, z0, zA, 1.03);
        const scalar speed = std::sqrt(sqr(exposed) + 0.5*magSqr(Uhost));
        const vector along(exposed + 0.5*0.35, 0, 0.5*0.02);
        EXPECT_NEAR(mag(U), speed, 2e-3*speed);
        EXPECT_NEAR(U.z()/mag(U), along.z()/mag(along), 2e-3);
    }
    // reaching above z_a: a grain of 40 mm centred at 0.07 (top 0.09)
    {
        const scalar D = 0.04, zc = 0.07;
        const scalar Z0 = 2.9*D/30;
        const vector U
        (
            model.velocity(zc, D, 0.04, 0.06, 0.14, 0.56, Ua, Uhost)
        );
        const scalar exposed = dragEquivalent(zc, 0.5*D, zE, Z0, zA, 1.03);
        EXPECT_NEAR(mag(U), exposed, 2e-3*exposed);
        EXPECT_LT(mag(U), 1.03);
    }
}


TEST(bedSurfaceLogLaw, BuriedGrainSeesItsHostCell)
{
    const bedSurfaceLogLaw model(2.9, 0.56);
    const vector Uhost(0.01, 0.002, -0.003);
    // z_e = 0.05; the grain's top at 0.045
    const vector U
    (
        model.velocity
        (
            0.04, 0.01, 0.04, 0.06, 0.28, 0.56, vector(1, 0, 0), Uhost
        )
    );
    EXPECT_EQ(U, Uhost);
}


TEST(bedSurfaceLogLaw, CellExtentAlongUp)
{
    const fvMesh& mesh = testing_demCoupling::mesh();
    // cells of 2 mm: the cell whose centre is (1, 2, 3) cells up
    const label celli = mesh.findCell(point(0.003, 0.005, 0.007));
    ASSERT_GE(celli, 0);
    scalar lo, hi;
    bedSurfaceLogLaw::verticalExtent(mesh, celli, vector(0, 0, 1), lo, hi);
    EXPECT_NEAR(lo, 0.006, 1e-12);
    EXPECT_NEAR(hi, 0.008, 1e-12);
    bedSurfaceLogLaw::verticalExtent(mesh, celli, vector(-1, 0, 0), lo, hi);
    EXPECT_NEAR(lo, -0.004, 1e-12);
    EXPECT_NEAR(hi, -0.002, 1e-12);
}


TEST(bedSurfaceLogLaw, BadCoefficientsStop)
{
    dictionary none;
    EXPECT_THROW(bedSurfaceLogLaw model(none), Foam::error);
    dictionary dict;
    dict.add("bedSurfaceLogLawCoeffs", dictionary());
    dict.subDictPtr("bedSurfaceLogLawCoeffs")->add("roughness", 2.9);
    // bedSolidFraction missing
    EXPECT_THROW(bedSurfaceLogLaw model(dict), Foam::error);
    dict.subDictPtr("bedSurfaceLogLawCoeffs")->add("bedSolidFraction", 1.2);
    EXPECT_THROW(bedSurfaceLogLaw model(dict), Foam::error);
    dict.subDictPtr("bedSurfaceLogLawCoeffs")->set("bedSolidFraction", 0.56);
    const bedSurfaceLogLaw model(dict);
    EXPECT_EQ(model.bedSolidFraction(), 0.56);
    dict.subDictPtr("bedSurfaceLogLawCoeffs")->set("roughness", -1.0);
    EXPECT_THROW(bedSurfaceLogLaw bad(dict), Foam::error);
}


// The sampler reads the coefficients only with fluidVelocity
// bedSurfaceLogLaw, and says so when they come without it or it without
// them (the message names the sub-dictionary)
TEST(bedSurfaceLogLaw, SamplerRefusesCoefficientsWithoutTheModel)
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
    stray.add("bedSurfaceLogLawCoeffs", dictionary());
    EXPECT_NE
    (
        messageOf(stray).find("is read only with fluidVelocity bedSurfaceLogLaw"),
        std::string::npos
    );

    dictionary missing;
    missing.add("fluidVelocity", "bedSurfaceLogLaw");
    EXPECT_NE
    (
        messageOf(missing).find("needs the sub-dictionary bedSurfaceLogLawCoeffs"),
        std::string::npos
    );
}
