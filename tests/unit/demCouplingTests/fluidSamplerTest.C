// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
// The velocity at a grain's top (fluidVelocity grainTop,
// fluidSampler::reconstructed) against closed forms on the unit-test
// mesh (1 cm cube, cells of 2 mm, walls all round):
// - a linear field u = (a z, b x, c y) is reconstructed exactly at any
//   point of an interior cell (Gauss linear gradients of a linear field
//   are exact on a uniform mesh), to 1e-12 of the field's range;
// - a step in u (0 below z = 4 mm, 1 above, the bed's top and the flow
//   over it) is not overshot: at the top of the first cell above the step
//   the unbounded reconstruction gives 1.475, the bounded one the largest
//   neighbour value, 1; in the cell below the step the reconstruction lies
//   inside the bounds (0.725) and is kept;
// - a linear scalar field (k, epsilon, the shear stress at the top:
//   velocityFluctuation sampledAt grainTop) likewise, and a point beyond
//   the upper neighbour is held at its value;
// - the value in the cell above a host cell (sampledAt cellAbove) is its
//   upper face neighbour's for gravity along -z, tilted 17 degrees and
//   along +x, the cell's own under the top wall, and the value across the
//   face where the patch above is coupled (marker values).

#include <gtest/gtest.h>
#include "testMain.H"
#include "fluidSampler.H"
#include "fvc.H"

using namespace Foam;
using namespace Foam::demCoupling;

namespace
{

// A field from its value at cell centres and boundary faces
template<class Type>
tmp<GeometricField<Type, fvPatchField, volMesh>> fieldOf
(
    const fvMesh& mesh,
    Type (*u)(const point&)
)
{
    auto tU = tmp<GeometricField<Type, fvPatchField, volMesh>>::New
    (
        IOobject("f", mesh.time().timeName(), mesh),
        mesh,
        dimensioned<Type>(dimless, Zero),
        calculatedFvPatchField<Type>::typeName
    );
    GeometricField<Type, fvPatchField, volMesh>& U = tU.ref();
    forAll(U, celli)
    {
        U[celli] = u(mesh.C()[celli]);
    }
    forAll(U.boundaryField(), patchi)
    {
        fvPatchField<Type>& Ub = U.boundaryFieldRef()[patchi];
        const vectorField& Cf = mesh.boundary()[patchi].Cf();
        forAll(Ub, facei)
        {
            Ub[facei] = u(Cf[facei]);
        }
    }
    return tU;
}

vector linearField(const point& x)
{
    return vector(300*x.z(), -200*x.x(), 100*x.y());
}

vector stepField(const point& x)
{
    return vector(x.z() > 0.004 ? 1 : 0, 0, 0);
}

scalar linearScalar(const point& x)
{
    return 2 + 50*x.x() + 400*x.z();
}

scalar linearScalarWithY(const point& x)
{
    return 2 + 50*x.x() + 400*x.z() + 7*x.y();
}

// The cell whose centre is (i, j, k) cells from the origin corner
label cellAt(const fvMesh& mesh, const label i, const label j, const label k)
{
    const point c(0.002*(i + 0.5), 0.002*(j + 0.5), 0.002*(k + 0.5));
    const label celli = mesh.findCell(c);
    EXPECT_GE(celli, 0);
    return celli;
}

} // End anonymous namespace


TEST(fluidSampler, TopVelocityIsExactForALinearField)
{
    const fvMesh& mesh = testing_demCoupling::mesh();
    const tmp<volVectorField> tU(fieldOf(mesh, linearField));
    const volTensorField gradU(fvc::grad(tU()));

    // An interior cell and points in it and up to a cell beyond it (a
    // grain's top lies up to d/2 above its centre)
    const label celli = cellAt(mesh, 2, 2, 2);
    const point C(mesh.C()[celli]);
    for (const vector& offset :
        {
            vector(0, 0, 0.0009), vector(0.0007, -0.0004, 0.0019),
            vector(-0.0009, 0.0009, 0.0001)
        })
    {
        const point p(C + offset);
        const vector u
        (
            fluidSampler::reconstructed(tU(), gradU, celli, p)
        );
        const vector expected(linearField(p));
        // The field's range over the mesh is 3 m/s
        EXPECT_NEAR(u.x(), expected.x(), 3e-12) << "at z = " << p.z();
        EXPECT_NEAR(u.y(), expected.y(), 3e-12) << "at z = " << p.z();
        EXPECT_NEAR(u.z(), expected.z(), 3e-12) << "at z = " << p.z();
    }
}


TEST(fluidSampler, TopVelocityDoesNotOvershootAStep)
{
    const fvMesh& mesh = testing_demCoupling::mesh();
    const tmp<volVectorField> tU(fieldOf(mesh, stepField));
    const volTensorField gradU(fvc::grad(tU()));

    // First cell above the step (centre z = 5 mm): gradient (1 - 0)/4 mm;
    // unbounded at z = 6.9 mm: 1 + 250*1.9e-3 = 1.475
    const label above = cellAt(mesh, 2, 2, 2);
    EXPECT_NEAR(gradU[above].zx(), 250, 1e-9);
    const vector uAbove
    (
        fluidSampler::reconstructed
        (
            tU(), gradU, above, mesh.C()[above] + vector(0, 0, 0.0019)
        )
    );
    EXPECT_DOUBLE_EQ(uAbove.x(), 1.0);

    // The cell below it (centre z = 3 mm): 0 + 250*2.9e-3 = 0.725, inside
    // [0, 1]: kept
    const label below = cellAt(mesh, 2, 2, 1);
    const vector uBelow
    (
        fluidSampler::reconstructed
        (
            tU(), gradU, below, mesh.C()[below] + vector(0, 0, 0.0029)
        )
    );
    EXPECT_NEAR(uBelow.x(), 0.725, 1e-12);
    EXPECT_DOUBLE_EQ(uBelow.y(), 0.0);
}


TEST(fluidSampler, TopScalarIsExactForALinearField)
{
    // k, epsilon and the shear stress at a grain's top (velocityFluctuation
    // sampledAt grainTop) take the same reconstruction: f = 2 + 50 x + 400 z
    const fvMesh& mesh = testing_demCoupling::mesh();
    const tmp<volScalarField> tf(fieldOf(mesh, linearScalar));
    const volScalarField& f = tf();
    const volVectorField gradF(fvc::grad(f));
    const label celli = cellAt(mesh, 1, 3, 2);
    const point p(mesh.C()[celli] + vector(0.0003, 0, 0.0015));
    // The field's range over the mesh is 4.5
    EXPECT_NEAR
    (
        fluidSampler::reconstructed(f, gradF, celli, p), linearScalar(p), 5e-12
    );
    // A point above the cell's neighbours' values is held at their largest
    const point far(mesh.C()[celli] + vector(0, 0, 0.006));
    const label above = cellAt(mesh, 1, 3, 3);
    EXPECT_DOUBLE_EQ
    (
        fluidSampler::reconstructed(f, gradF, celli, far), f[above]
    );
}


TEST(fluidSampler, CellAboveIsTheUpperFaceNeighbour)
{
    // k, epsilon and the shear stress in the cell above a grain's host
    // cell (velocityFluctuation sampledAt cellAbove): the face neighbour
    // across the face whose outward normal points most nearly up; the
    // host cell itself under a wall. f = 2 + 50 x + 400 z + 7 y.
    const fvMesh& mesh = testing_demCoupling::mesh();
    const tmp<volScalarField> tf(fieldOf(mesh, linearScalarWithY));
    const volScalarField& f = tf();
    const PtrList<scalarField> across
    (
        fluidSampler::valuesAcrossCoupledPatches(f)
    );
    const label celli = cellAt(mesh, 1, 3, 2);
    // Gravity along -z, and tilted by 17 degrees (still the top face)
    EXPECT_DOUBLE_EQ
    (
        fluidSampler::valueInCellAbove(f, across, celli, vector(0, 0, 1)),
        f[cellAt(mesh, 1, 3, 3)]
    );
    EXPECT_DOUBLE_EQ
    (
        fluidSampler::valueInCellAbove
        (
            f, across, celli, vector(0.3, 0, 1)/mag(vector(0.3, 0, 1))
        ),
        f[cellAt(mesh, 1, 3, 3)]
    );
    // Gravity along +x: "above" is the neighbour at lower x
    EXPECT_DOUBLE_EQ
    (
        fluidSampler::valueInCellAbove(f, across, celli, vector(-1, 0, 0)),
        f[cellAt(mesh, 0, 3, 2)]
    );
    // The top layer, under the wall: its own value
    const label top = cellAt(mesh, 1, 3, 4);
    EXPECT_DOUBLE_EQ
    (
        fluidSampler::valueInCellAbove(f, across, top, vector(0, 0, 1)),
        f[top]
    );

    // Across a coupled patch (cyclic, processor) the neighbour's value:
    // the top patch given marker values as if it were coupled
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    label topFace = -1;
    for (const label facei : mesh.cells()[top])
    {
        if (!mesh.isInternalFace(facei) && mesh.faceAreas()[facei].z() > 0)
        {
            topFace = facei;
        }
    }
    ASSERT_GE(topFace, 0);
    const label topPatch = patches.whichPatch(topFace);
    PtrList<scalarField> coupled(patches.size());
    coupled.set(topPatch, new scalarField(patches[topPatch].size()));
    forAll(coupled[topPatch], facei)
    {
        coupled[topPatch][facei] = 1000 + facei;
    }
    EXPECT_DOUBLE_EQ
    (
        fluidSampler::valueInCellAbove(f, coupled, top, vector(0, 0, 1)),
        1000 + topFace - patches[topPatch].start()
    );
}
