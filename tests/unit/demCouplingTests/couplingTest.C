// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
// Locating particles, the pressure-gradient force, and the momentum
// coupling's fluid sources, on the 5 x 5 x 5 test mesh (1 cm cube).

#include <gtest/gtest.h>
#include "testMain.H"
#include "particleLocator.H"
#include "voidFractionModel.H"
#include "forceModel.H"
#include "momentumCouplingModel.H"
#include "volFields.H"
#include "Random.H"
#include "zeroGradientFvPatchFields.H"
#include "mathematicalConstants.H"

using namespace Foam;
using namespace Foam::demCoupling;

namespace
{
particleData randomParticles(const fvMesh& mesh, const label n, const label seed)
{
    Random rnd(seed);
    const boundBox& bb = mesh.bounds();
    particleData p;
    p.resize(n);
    for (label i = 0; i < n; ++i)
    {
        p.tag[i] = i + 1;
        p.position[i] =
            bb.min() + cmptMultiply(rnd.sample01<vector>(), bb.span());
        p.velocity[i] = rnd.sample01<vector>() - vector::uniform(0.5);
        p.diameter[i] = 2e-4 + 6e-4*rnd.sample01<scalar>();
        p.density[i] = 2500;
    }
    return p;
}

// The cell holding p by testing every cell: the reference for the locator
label bruteForceCell(const fvMesh& mesh, const point& p)
{
    for (label c = 0; c < mesh.nCells(); ++c)
    {
        if (mesh.pointInCell(p, c, polyMesh::CELL_TETS))
        {
            return c;
        }
    }
    return -1;
}

template<class Type>
tmp<GeometricField<Type, fvPatchField, volMesh>> newField
(
    const fvMesh& mesh, const word& name, const dimensioned<Type>& v
)
{
    return tmp<GeometricField<Type, fvPatchField, volMesh>>::New
    (
        IOobject(name, mesh.time().timeName(), mesh),
        mesh,
        v,
        zeroGradientFvPatchField<Type>::typeName
    );
}
}


TEST(particleLocator, AgreesWithBruteForceAndFollowsParticles)
{
    const fvMesh& mesh = testing_demCoupling::mesh();
    particleLocator locator(mesh);
    particleData p = randomParticles(mesh, 200, 7);

    locator.locate(p, particleCombine());
    forAll(p.position, i)
    {
        EXPECT_EQ(p.cell[i], bruteForceCell(mesh, p.position[i])) << i;
    }
    EXPECT_EQ(locator.lost(), 0);

    // Move every particle by less than a cell along one axis: it stays in
    // its cell or enters a face neighbour, both found without the octree
    Random rnd(99);
    const scalar dx = Foam::cbrt(mesh.V()[0]);
    forAll(p.position, i)
    {
        vector step(Zero);
        step[i % 3] = 0.9*dx*(rnd.sample01<scalar>() - 0.5);
        p.position[i] += step;
        const boundBox& bb = mesh.bounds();
        p.position[i] = max(min(p.position[i], bb.max() - vector::uniform(1e-9)),
                            bb.min() + vector::uniform(1e-9));
    }
    locator.locate(p, particleCombine());
    forAll(p.position, i)
    {
        EXPECT_EQ(p.cell[i], bruteForceCell(mesh, p.position[i])) << i;
    }
    EXPECT_EQ(locator.hintHits(), p.size());
}


TEST(particleLocator, CountsParticlesOutsideTheMesh)
{
    const fvMesh& mesh = testing_demCoupling::mesh();
    particleLocator locator(mesh);
    particleData p = randomParticles(mesh, 10, 3);
    p.position[2] = point(0.5, 0.005, 0.005);      // 0.5 m off a 1 cm cube
    p.position[7] = point(0.005, 0.005, -0.001);   // just below the bottom
    locator.locate(p, particleCombine());
    EXPECT_EQ(locator.lost(), 2);
    EXPECT_EQ(p.cell[2], -1);
    EXPECT_EQ(p.cell[7], -1);
    EXPECT_GE(p.cell[0], 0);
}


// Hydrostatic water: grad(p) = rho g, so F = -V_p grad(p) is Archimedes'
// buoyancy rho_f V_p |g| upwards
TEST(pressureGradientForce, IsArchimedesBuoyancyInHydrostaticWater)
{
    dictionary dict;
    dict.add("forces", wordList{"pressureGradient"});
    PtrList<forceModel> models(forceModel::NewList(dict));
    ASSERT_EQ(models.size(), 1);
    EXPECT_FALSE(models[0].reactsOnFluid());

    particleFluidState s;
    s.d = 1e-3;
    s.rhoP = 2500;
    s.rhoF = 1000;
    s.gradP = vector(0, 0, -1000*9.81);
    const particleForce f(models[0].force(s));
    const scalar Vp = constant::mathematical::pi/6*1e-9;
    EXPECT_NEAR(f.total(s).z(), 1000*9.81*Vp, 1e-12*1000*9.81*Vp);
    EXPECT_DOUBLE_EQ(f.total(s).x(), 0);
    EXPECT_DOUBLE_EQ(f.K, 0);
}


// Both momentum couplings conserve momentum: the fluid receives, summed
// over cells, exactly minus the reacting force on the particles
class momentumCouplingTest : public ::testing::TestWithParam<word> {};

TEST_P(momentumCouplingTest, FluidReceivesMinusTheParticleForce)
{
    const fvMesh& mesh = testing_demCoupling::mesh();
    particleData p = randomParticles(mesh, 30, 11);
    particleLocator locator(mesh);
    locator.locate(p, particleCombine());

    dictionary dict;
    dict.add("voidFraction", "centre");
    dict.add("minVoidFraction", 0.1);
    dict.add("momentumCoupling", GetParam());
    autoPtr<voidFractionModel> vf(voidFractionModel::New(dict, mesh));
    autoPtr<momentumCouplingModel> mc(momentumCouplingModel::New(dict, mesh));

    auto eps = newField(mesh, "eps", dimensionedScalar("one", dimless, 1.0));
    vf->update(p, particleCombine(), eps.ref());

    Random rnd(5);
    scalarList K(p.size());
    List<vector> Uf(p.size()), Fx(p.size());
    vector totalOnParticles(Zero);
    forAll(K, i)
    {
        K[i] = 1e-5*(1 + rnd.sample01<scalar>());
        Uf[i] = rnd.sample01<vector>();
        Fx[i] = 1e-6*(rnd.sample01<vector>() - vector::uniform(0.5));
        totalOnParticles += K[i]*(Uf[i] - p.velocity[i]) + Fx[i];
    }

    auto Ksl = newField(mesh, "Ksl",
        dimensionedScalar("zero", dimDensity/dimTime, 0.0));
    auto Us = newField(mesh, "Us", dimensionedVector(dimVelocity, Zero));
    auto fExp = newField(mesh, "fExplicit",
        dimensionedVector(dimForce/dimVolume, Zero));
    mc->assemble(p, vf(), K, Uf, p.velocity, Fx, Ksl.ref(), Us.ref(), fExp.ref());

    // Fluid source per cell, Ksl (Us - U) + fExplicit, with U the fluid
    // velocity the particles saw (their K-weighted Uf per cell): summed
    // over cells it is - sum_i [K_i (Uf_i - v_i) + F_i], for both models
    const scalarField& V = mesh.V();
    vectorField UfCell(mesh.nCells(), Zero);
    scalarField Kcell(mesh.nCells(), 0);
    forAll(p.cell, i)
    {
        UfCell[p.cell[i]] += K[i]*Uf[i];
        Kcell[p.cell[i]] += K[i];
    }
    vector totalOnFluid(Zero);
    forAll(V, c)
    {
        if (Kcell[c] > 0) UfCell[c] /= Kcell[c];
        totalOnFluid += V[c]*(Ksl()[c]*(Us()[c] - UfCell[c]) + fExp()[c]);
    }
    EXPECT_LT
    (
        mag(totalOnFluid + totalOnParticles),
        1e-10*mag(totalOnParticles)
    );

    if (GetParam() == "explicit")
    {
        EXPECT_EQ(gMax(Ksl()), 0);
    }
    else
    {
        // The drag is implicit: sum V Ksl = sum K
        EXPECT_NEAR(gSum(Ksl()*V), sum(K), 1e-12*sum(K));
    }
}

INSTANTIATE_TEST_SUITE_P
(
    models,
    momentumCouplingTest,
    ::testing::Values(word("explicit"), word("semiImplicit"))
);
