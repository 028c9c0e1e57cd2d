// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
// Void-fraction models on a 5 x 5 x 5 mesh of a 1 cm cube: particle volume
// is conserved, sum (1 - eps) V = sum V_p, and the floor is counted.

#include <gtest/gtest.h>
#include "testMain.H"
#include "voidFractionModel.H"
#include "volFields.H"
#include "Random.H"
#include "zeroGradientFvPatchFields.H"

using namespace Foam;
using namespace Foam::demCoupling;

namespace
{
autoPtr<volScalarField> newEps(const fvMesh& mesh)
{
    return autoPtr<volScalarField>::New
    (
        IOobject("voidfraction", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar("one", dimless, 1.0),
        zeroGradientFvPatchScalarField::typeName
    );
}

dictionary modelDict(const word& model, const scalar minEps)
{
    dictionary dict;
    dict.add("voidFraction", model);
    dict.add("minVoidFraction", minEps);
    return dict;
}

// n particles at random positions, diameters in [dMin, dMax]
particleData randomParticles
(
    const fvMesh& mesh, const label n, const scalar dMin, const scalar dMax
)
{
    Random rnd(1234);
    const boundBox& bb = mesh.bounds();
    particleData p;
    p.resize(n);
    for (label i = 0; i < n; ++i)
    {
        p.position[i] = bb.min() + cmptMultiply(rnd.sample01<vector>(), bb.span());
        p.diameter[i] = dMin + (dMax - dMin)*rnd.sample01<scalar>();
        p.density[i] = 2500;
        p.cell[i] = mesh.findCell(p.position[i]);
        p.hostProc[i] = p.cell[i] >= 0 ? 0 : -1;
    }
    return p;
}
}


TEST(centreVoidFraction, ConservesParticleVolume)
{
    const fvMesh& mesh = testing_demCoupling::mesh();
    const scalar dx = Foam::cbrt(mesh.V()[0]);   // 2 mm

    // 40 particles of 0.1 ... 0.5 dx: no cell reaches the floor
    const particleData p = randomParticles(mesh, 40, 0.1*dx, 0.5*dx);

    auto model = voidFractionModel::New(modelDict("centre", 0.05), mesh);
    auto eps = newEps(mesh);
    model->update(p, particleCombine(), *eps);

    scalar Vp = 0;
    forAll(p.diameter, i) { Vp += p.volume(i); }
    const scalar Vsolid = gSum((1 - eps->primitiveField())*mesh.V());

    ASSERT_EQ(model->floorHits(), 0);
    EXPECT_NEAR(Vsolid, Vp, 1e-12*Vp);

    // each particle's weights sum to one, on its host cell only
    forAll(p.cell, i)
    {
        ASSERT_EQ(model->cells(i).size(), 1);
        EXPECT_EQ(model->cells(i)[0], p.cell[i]);
        EXPECT_DOUBLE_EQ(model->weights(i)[0], 1.0);
    }
}


TEST(centreVoidFraction, FloorIsAppliedAndCounted)
{
    const fvMesh& mesh = testing_demCoupling::mesh();
    const scalar dx = Foam::cbrt(mesh.V()[0]);

    // one particle as large as the cell: V_p/V_c = pi/6 = 0.52 -> eps 0.48
    particleData p;
    p.resize(1);
    p.position[0] = mesh.C()[62];
    p.cell[0] = 62;
    p.diameter[0] = dx;

    auto eps = newEps(mesh);

    auto loose = voidFractionModel::New(modelDict("centre", 0.2), mesh);
    loose->update(p, particleCombine(), *eps);
    EXPECT_NEAR((*eps)[62], 1 - constant::mathematical::pi/6, 1e-12);
    EXPECT_EQ(loose->floorHits(), 0);

    auto tight = voidFractionModel::New(modelDict("centre", 0.6), mesh);
    tight->update(p, particleCombine(), *eps);
    EXPECT_DOUBLE_EQ((*eps)[62], 0.6);
    EXPECT_EQ(tight->floorHits(), 1);
    EXPECT_EQ(tight->totalFloorHits(), 1);
}


TEST(centreVoidFraction, ParticleOutsideMeshIsSkipped)
{
    const fvMesh& mesh = testing_demCoupling::mesh();
    particleData p;
    p.resize(1);
    p.position[0] = point(1, 1, 1);   // far outside the 1 cm cube
    p.diameter[0] = 1e-3;
    p.cell[0] = mesh.findCell(p.position[0]);
    ASSERT_EQ(p.cell[0], -1);

    auto model = voidFractionModel::New(modelDict("centre", 0.2), mesh);
    auto eps = newEps(mesh);
    model->update(p, particleCombine(), *eps);
    EXPECT_DOUBLE_EQ(gMin(eps->primitiveField()), 1.0);
}


// divided: particle volume is conserved; a particle inside one cell stays
// there; one that straddles a face shares its volume like the sphere's cap
TEST(dividedVoidFraction, ConservesVolumeAndSplitsAcrossFaces)
{
    const fvMesh& mesh = testing_demCoupling::mesh();
    const scalar dx = Foam::cbrt(mesh.V()[0]);   // 2 mm

    const particleData p = randomParticles(mesh, 40, 0.1*dx, 0.5*dx);
    auto model = voidFractionModel::New(modelDict("divided", 0.05), mesh);
    auto eps = newEps(mesh);
    model->update(p, particleCombine(), *eps);

    scalar Vp = 0;
    forAll(p.diameter, i)
    {
        Vp += p.volume(i);
        EXPECT_NEAR(sum(model->weights(i)), 1.0, 1e-12);
    }
    EXPECT_NEAR(gSum((1 - eps->primitiveField())*mesh.V()), Vp, 1e-12*Vp);

    // Centre at a cell centre, d = dx/2: wholly inside that cell
    particleData q;
    q.resize(1);
    q.position[0] = mesh.C()[62];
    q.cell[0] = 62;
    q.hostProc[0] = 0;
    q.diameter[0] = 0.5*dx;
    model->update(q, particleCombine(), *eps);
    ASSERT_EQ(model->cells(0).size(), 1);
    EXPECT_EQ(model->cells(0)[0], 62);

    // Centre r/2 below the face between cell 62 and its +x neighbour: the
    // cap beyond the face holds 5/32 = 0.156 of the volume; 64 points
    // resolve it to about one point pair (+- 0.03)
    const scalar r = 0.5*dx;
    q.diameter[0] = 2*r;
    q.position[0] = mesh.C()[62] + vector(0.5*dx - 0.5*r, 0, 0);
    model->update(q, particleCombine(), *eps);
    const label across = mesh.findCell(mesh.C()[62] + vector(dx, 0, 0));
    scalar wAcross = 0;
    forAll(model->cells(0), k)
    {
        if (model->cells(0)[k] == across) wAcross += model->weights(0)[k];
    }
    EXPECT_NEAR(wAcross, 5.0/32.0, 0.03);
}


namespace
{
dictionary virtualSphereDict(const scalar minEps)
{
    dictionary dict(modelDict("virtualSphere", minEps));
    dictionary coeffs;
    coeffs.add("diameterRatio", 4.0);
    coeffs.add("sizeThreshold", 0.25);
    dict.add("virtualSphereCoeffs", coeffs);
    return dict;
}

// Any model's dictionary, with the coefficients of the kernel models
dictionary anyModelDict(const word& model, const scalar minEps)
{
    if (model == "virtualSphere")
    {
        return virtualSphereDict(minEps);
    }
    dictionary dict(modelDict(model, minEps));
    if (model == "diffusion")
    {
        dictionary coeffs;
        coeffs.add("bandwidth", 0.004);     // 2 cells of the test mesh
        coeffs.add("nSteps", 3);
        dict.add("diffusionCoeffs", coeffs);
    }
    return dict;
}

// Particle 0's cells are the expected set, and each holds the same solid
// fraction V_p / V_VS (V_VS the set's volume)
void expectSetAndEqualShares
(
    const fvMesh& mesh,
    const voidFractionModel& vf,
    const volScalarField& eps,
    const particleData& p,
    const labelHashSet& expected
)
{
    const labelUList cells(vf.cells(0));
    EXPECT_EQ(label(cells.size()), expected.size())
        << p.position[0].x() << " " << p.position[0].y() << " "
        << p.position[0].z();
    scalar VVS = 0;
    for (const label c : cells)
    {
        EXPECT_TRUE(expected.found(c)) << "cell " << c;
        VVS += mesh.V()[c];
    }
    for (const label c : cells)
    {
        EXPECT_NEAR(1 - eps[c], p.volume(0)/VVS, 1e-12);
    }
}

// Every cell whose centre is within R of x, and the host: the reference set
labelHashSet bruteForceSphere
(
    const fvMesh& mesh, const point& x, const scalar R, const label host
)
{
    labelHashSet cells;
    forAll(mesh.C(), c)
    {
        if (magSqr(mesh.C()[c] - x) <= sqr(R)) cells.insert(c);
    }
    cells.insert(host);
    return cells;
}
}


// Each model: weights of every particle sum to one (exact volume
// conservation) for particles of 0.1 ... 2 dx; where no floor bites the eps
// field holds exactly the particles' volume
TEST(voidFractionModels, ConserveVolumeForParticlesUpToTwoCells)
{
    const fvMesh& mesh = testing_demCoupling::mesh();
    const scalar dx = Foam::cbrt(mesh.V()[0]);

    for (const word model : {"centre", "divided", "virtualSphere", "diffusion"})
    {
        const particleData p = randomParticles(mesh, 12, 0.1*dx, 2*dx);
        auto vf = voidFractionModel::New(anyModelDict(model, 1e-6), mesh);
        auto eps = newEps(mesh);
        vf->update(p, particleCombine(), *eps);

        scalar Vp = 0, Vweighted = 0;
        forAll(p.diameter, i)
        {
            Vp += p.volume(i);
            EXPECT_NEAR(sum(vf->weights(i)), 1.0, 1e-12) << model << " " << i;
            Vweighted += sum(vf->weights(i))*p.volume(i);
        }
        EXPECT_NEAR(Vweighted, Vp, 1e-12*Vp) << model;

        // One particle at a time: no floor, eps holds its volume exactly
        forAll(p.diameter, i)
        {
            particleData one;
            one.resize(1);
            one.position[0] = p.position[i];
            one.diameter[0] = p.diameter[i];
            one.cell[0] = p.cell[i];
            one.hostProc[0] = 0;
            vf->update(one, particleCombine(), *eps);
            if (vf->floorHits() == 0)
            {
                EXPECT_NEAR
                (
                    gSum((1 - eps->primitiveField())*mesh.V()),
                    one.volume(0),
                    1e-10*one.volume(0)
                ) << model << " particle " << i;
            }
        }
    }
}


// Virtual sphere: a particle at a corner shared by 8 cells, and one next to
// a wall, spread over exactly the cells whose centres lie within 2 d (the
// host always), each with the same solid fraction (weight V_c / V_VS)
TEST(virtualSphereVoidFraction, CellSetStraddlingCellsAndNearAWall)
{
    const fvMesh& mesh = testing_demCoupling::mesh();
    const scalar dx = Foam::cbrt(mesh.V()[0]);
    auto vf = voidFractionModel::New(virtualSphereDict(0.05), mesh);
    auto eps = newEps(mesh);

    const point corner = mesh.C()[62] + 0.5*vector(dx, dx, dx);
    const point nearWall = point(0.1*dx, 0.5*mesh.bounds().span().y(), 0.005);

    for (const point& x : {corner, nearWall})
    {
        particleData p;
        p.resize(1);
        p.position[0] = x;
        p.diameter[0] = 0.6*dx;              // > 0.25 dx: spread
        p.cell[0] = mesh.findCell(x);
        p.hostProc[0] = 0;
        ASSERT_GE(p.cell[0], 0);
        vf->update(p, particleCombine(), *eps);

        const labelHashSet expected
        (
            bruteForceSphere(mesh, x, 2*0.6*dx, p.cell[0])
        );
        expectSetAndEqualShares(mesh, *vf, *eps, p, expected);
        EXPECT_NEAR(gSum((1 - eps->primitiveField())*mesh.V()),
                    p.volume(0), 1e-12*p.volume(0));
    }

    // at the corner of 8 cells with R = 1.2 dx: exactly those 8 cells
    {
        particleData p;
        p.resize(1);
        p.position[0] = corner;
        p.diameter[0] = 0.6*dx;
        p.cell[0] = mesh.findCell(corner);
        p.hostProc[0] = 0;
        vf->update(p, particleCombine(), *eps);
        EXPECT_EQ(vf->cells(0).size(), 8);
    }

    // below the threshold (d = 0.2 dx <= 0.25 dx): the centre model
    {
        particleData p;
        p.resize(1);
        p.position[0] = corner - vector::uniform(0.1*dx);
        p.diameter[0] = 0.2*dx;
        p.cell[0] = mesh.findCell(p.position[0]);
        p.hostProc[0] = 0;
        vf->update(p, particleCombine(), *eps);
        ASSERT_EQ(vf->cells(0).size(), 1);
        EXPECT_EQ(vf->cells(0)[0], p.cell[0]);
    }
}


// The oblate spheroid (verticalDiameterRatio k_v < k; the unit-test
// mesh's gravity is along -z): a grain of 0.6 dx at a cell centre with
// k = 4 (1.2 dx across) and k_v = 2 (0.6 dx along z) takes its host and
// the four face neighbours across gravity, not the two along it (the
// sphere of 4 d takes all seven); off-centre and at a corner the set is
// the brute-force spheroid's, and each cell of it holds V_p/V_VS
TEST(virtualSphereVoidFraction, SpheroidKeepsTheVolumeWithinItsHeight)
{
    const fvMesh& mesh = testing_demCoupling::mesh();
    const scalar dx = Foam::cbrt(mesh.V()[0]);
    dictionary dict(virtualSphereDict(0.05));
    dict.subDictPtr("virtualSphereCoeffs")->add("verticalDiameterRatio", 2.0);
    auto vf = voidFractionModel::New(dict, mesh);
    auto sphere = voidFractionModel::New(virtualSphereDict(0.05), mesh);
    auto eps = newEps(mesh);

    const scalar d = 0.6*dx, R = 2*d, Rv = d;
    const point centre = mesh.C()[62];
    for
    (
        const point& x :
        {
            centre,
            centre + vector(0.3*dx, -0.2*dx, 0.35*dx),
            centre + 0.5*vector(dx, dx, dx)
        }
    )
    {
        particleData p;
        p.resize(1);
        p.position[0] = x;
        p.diameter[0] = d;
        p.cell[0] = mesh.findCell(x);
        p.hostProc[0] = 0;
        ASSERT_GE(p.cell[0], 0);
        vf->update(p, particleCombine(), *eps);

        labelHashSet expected;
        forAll(mesh.C(), c)
        {
            const vector r(mesh.C()[c] - x);
            if (sqr(r.x()/R) + sqr(r.y()/R) + sqr(r.z()/Rv) <= 1)
            {
                expected.insert(c);
            }
        }
        expected.insert(p.cell[0]);
        expectSetAndEqualShares(mesh, *vf, *eps, p, expected);
        const labelUList cells(vf->cells(0));
        if (x == centre)
        {
            EXPECT_EQ(cells.size(), 5);
            for (const label c : cells)
            {
                EXPECT_LT(mag(mesh.C()[c].z() - x.z()), 1e-12*dx);
            }
            sphere->update(p, particleCombine(), *eps);
            EXPECT_EQ(sphere->cells(0).size(), 7);
        }
    }

    // k_v above k, or below 1, stops with the keyword named
    for (const scalar kv : {5.0, 0.5})
    {
        dictionary bad(virtualSphereDict(0.05));
        bad.subDictPtr("virtualSphereCoeffs")->add("verticalDiameterRatio", kv);
        EXPECT_THROW(voidFractionModel::New(bad, mesh), Foam::error) << kv;
    }
}



// One kernel for what a particle gives and what it sees: for every model,
// sum_c V_c spread(X)_c = sum_i X_i (conservation), and
// sum_i X_i sample(f)_i = sum_c V_c spread(X)_c f_c (the sampling is the
// adjoint of the spreading), for random X and a random field f
TEST(voidFractionModels, SpreadConservesAndSampleIsItsAdjoint)
{
    const fvMesh& mesh = testing_demCoupling::mesh();
    const scalar dx = Foam::cbrt(mesh.V()[0]);
    Random rnd(77);

    auto f = newEps(mesh);
    forAll(f(), c)
    {
        f.ref()[c] = rnd.sample01<scalar>();
    }
    f->correctBoundaryConditions();

    for (const word model : {"centre", "divided", "virtualSphere", "diffusion"})
    {
        const particleData p = randomParticles(mesh, 15, 0.2*dx, 1.5*dx);
        auto vf = voidFractionModel::New(anyModelDict(model, 1e-6), mesh);
        vf->update(p, particleCombine(), *newEps(mesh));

        scalarList X(p.size());
        forAll(X, i) { X[i] = 1 + rnd.sample01<scalar>(); }

        const scalarField XCell(vf->spread(X));
        const scalarList fi(vf->sample(*f));

        EXPECT_NEAR(gSum(XCell*mesh.V()), sum(X), 1e-10*sum(X)) << model;
        scalar lhs = 0;
        forAll(X, i) { lhs += X[i]*fi[i]; }
        const scalar rhs = gSum(XCell*f->primitiveField()*mesh.V());
        EXPECT_NEAR(lhs, rhs, 1e-9*mag(rhs)) << model;
    }
}


// diffusion: a particle in the centre cell of the cube spreads its volume
// symmetrically (equal in the 6 face neighbours), less in the host than
// the centre model, and the total is conserved
TEST(diffusionVoidFraction, SpreadsSymmetricallyAndConserves)
{
    const fvMesh& mesh = testing_demCoupling::mesh();
    const scalar dx = Foam::cbrt(mesh.V()[0]);
    auto vf = voidFractionModel::New(anyModelDict("diffusion", 1e-6), mesh);
    auto eps = newEps(mesh);

    particleData p;
    p.resize(1);
    p.position[0] = mesh.C()[62];
    p.cell[0] = 62;
    p.hostProc[0] = 0;
    p.diameter[0] = dx;
    vf->update(p, particleCombine(), *eps);

    const scalarField solid(1 - eps->primitiveField());
    const labelList& nbrs = mesh.cellCells()[62];
    ASSERT_EQ(nbrs.size(), 6);
    for (const label c : nbrs)
    {
        EXPECT_NEAR(solid[c], solid[nbrs[0]], 1e-10*solid[nbrs[0]]);
        EXPECT_GT(solid[c], 0);
        EXPECT_LT(solid[c], solid[62]);
    }
    EXPECT_LT(solid[62], p.volume(0)/mesh.V()[62]);
    EXPECT_NEAR(gSum(solid*mesh.V()), p.volume(0), 1e-10*p.volume(0));
}


// voidFractionFloor spill: the solid beyond 1 - minVoidFraction moves to the
// face neighbours in proportion to their room (solidSpill), conserving
// sum (1 - eps) V where clip loses it
TEST(voidFractionFloor, SpillSharesTheExcessAmongTheNeighbours)
{
    const fvMesh& mesh = testing_demCoupling::mesh();
    const scalar Vc = mesh.V()[62];
    const scalar dx = Foam::cbrt(Vc);

    // one particle of 1.3 cells' volume in the centre cell (62) and one of
    // 0.9 in a corner cell (0), floor 0.2: excesses 0.5 Vc and 0.1 Vc
    particleData p;
    p.resize(2);
    const label cells[2] = {62, 0};
    const scalar volumes[2] = {1.3, 0.9};
    for (label i = 0; i < 2; ++i)
    {
        p.position[i] = mesh.C()[cells[i]];
        p.cell[i] = cells[i];
        p.hostProc[i] = 0;
        p.density[i] = 2500;
        p.diameter[i] = Foam::cbrt(6*volumes[i]*Vc/constant::mathematical::pi);
    }
    ASSERT_GT(p.diameter[0], dx);

    dictionary dict(modelDict("centre", 0.2));
    dict.add("voidFractionFloor", "spill");
    auto model = voidFractionModel::New(dict, mesh);
    auto eps = newEps(mesh);
    model->update(p, particleCombine(), *eps);

    // the centre cell's six neighbours are empty: each takes 0.5/6; the
    // corner cell has three (two walls): each takes 0.1/3
    EXPECT_NEAR((*eps)[62], 0.2, 1e-12);
    for (const label n : {61, 63, 57, 67, 37, 87})
    {
        EXPECT_NEAR((*eps)[n], 1 - 0.5/6, 1e-12) << "cell " << n;
    }
    EXPECT_NEAR((*eps)[0], 0.2, 1e-12);
    for (const label n : {1, 5, 25})
    {
        EXPECT_NEAR((*eps)[n], 1 - 0.1/3, 1e-12) << "cell " << n;
    }
    EXPECT_EQ(model->floorHits(), 0);
    EXPECT_EQ(model->spilledCells(), 2);

    const scalar Vp = p.volume(0) + p.volume(1);
    EXPECT_NEAR(gSum((1 - eps->primitiveField())*mesh.V()), Vp, 1e-12*Vp);

    // clip, the default, loses the excess and counts both cells
    auto clip = voidFractionModel::New(modelDict("centre", 0.2), mesh);
    clip->update(p, particleCombine(), *eps);
    EXPECT_EQ(clip->floorHits(), 2);
    EXPECT_NEAR
    (
        gSum((1 - eps->primitiveField())*mesh.V()), Vp - 0.6*Vc, 1e-12*Vp
    );

    // a word that is neither stops the run
    dictionary bad(modelDict("centre", 0.2));
    bad.add("voidFractionFloor", "spil");
    EXPECT_THROW(voidFractionModel::New(bad, mesh), Foam::error);
}


// Excess behind full cells: the centre cell (62) holds 1.3 cells' volume
// and its six neighbours each hold exactly the cap (0.8, floor 0.2). The
// first pass pushes 0.5/6 through each neighbour; the second passes it on to
// each one's five other neighbours, 0.5/30 apiece: the cell two steps along
// x (60) ends at 1 - 0.5/30, a cell next to two of them (56) at 1 - 2 0.5/30
TEST(voidFractionFloor, SpillPassesExcessThroughFullCells)
{
    const fvMesh& mesh = testing_demCoupling::mesh();
    const scalar Vc = mesh.V()[62];

    const labelList cells({62, 61, 63, 57, 67, 37, 87});
    particleData p;
    p.resize(cells.size());
    forAll(cells, i)
    {
        p.position[i] = mesh.C()[cells[i]];
        p.cell[i] = cells[i];
        p.hostProc[i] = 0;
        p.density[i] = 2500;
        const scalar volume = i == 0 ? 1.3 : 0.8;
        p.diameter[i] = Foam::cbrt(6*volume*Vc/constant::mathematical::pi);
    }
    scalar Vp = 0;
    forAll(p.diameter, i) { Vp += p.volume(i); }

    dictionary dict(modelDict("centre", 0.2));
    dict.add("voidFractionFloor", "spill");
    auto model = voidFractionModel::New(dict, mesh);
    auto eps = newEps(mesh);
    model->update(p, particleCombine(), *eps);

    EXPECT_EQ(model->floorHits(), 0);
    for (const label c : cells)
    {
        EXPECT_NEAR((*eps)[c], 0.2, 1e-12) << "cell " << c;
    }
    EXPECT_NEAR((*eps)[60], 1 - 0.5/30, 1e-12);
    EXPECT_NEAR((*eps)[56], 1 - 2*0.5/30, 1e-12);
    EXPECT_NEAR(gSum((1 - eps->primitiveField())*mesh.V()), Vp, 1e-12*Vp);
}


// A random packing: 24 grains of 0.9-1.3 dx in the 27 cells around the
// centre (a mean solid fraction near 0.6) put several cells beyond the cap
// of 0.7; the spill leaves none there and keeps the volume
TEST(voidFractionFloor, SpillEmptiesARandomPackingConservingVolume)
{
    const fvMesh& mesh = testing_demCoupling::mesh();
    const scalar dx = Foam::cbrt(mesh.V()[62]);

    Random rnd(77);
    particleData p;
    p.resize(24);
    forAll(p.diameter, i)
    {
        p.position[i] = mesh.C()[62]
          + 1.4*dx*(2*rnd.sample01<vector>() - vector::one);
        p.cell[i] = mesh.findCell(p.position[i]);
        p.hostProc[i] = 0;
        p.density[i] = 2500;
        p.diameter[i] = (0.9 + 0.4*rnd.sample01<scalar>())*dx;
    }
    scalar Vp = 0;
    forAll(p.diameter, i) { Vp += p.volume(i); }

    auto eps = newEps(mesh);
    auto clip = voidFractionModel::New(modelDict("centre", 0.3), mesh);
    clip->update(p, particleCombine(), *eps);
    ASSERT_GE(clip->floorHits(), 3);

    dictionary dict(modelDict("centre", 0.3));
    dict.add("voidFractionFloor", "spill");
    auto model = voidFractionModel::New(dict, mesh);
    model->update(p, particleCombine(), *eps);
    EXPECT_EQ(model->floorHits(), 0);
    EXPECT_EQ(model->spilledCells(), clip->floorHits());
    EXPECT_GE(gMin(eps->primitiveField()), 0.3 - 1e-12);
    EXPECT_NEAR(gSum((1 - eps->primitiveField())*mesh.V()), Vp, 1e-12*Vp);
}
