// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "divided.H"
#include "meshReach.H"
#include "addToRunTimeSelectionTable.H"
#include "particleLocator.H"

namespace Foam
{
namespace demCoupling
{
namespace voidFractionModels
{
    defineTypeNameAndDebug(divided, 0);
    addToRunTimeSelectionTable(voidFractionModel, divided, dictionary);
}
}
}


Foam::demCoupling::voidFractionModels::divided::divided
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    voidFractionModel(dict, mesh),
    unitPoints_()
{
    // 32 points of the Halton sequence (bases 2, 3, 5) inside the unit
    // sphere and their mirror images: 64 equal shares of the volume, centred
    // on the particle, whose coordinates (nearly all) differ, so a particle
    // hands its volume across a mesh-aligned face in many small parts
    auto halton = [](label i, const label base)
    {
        scalar f = 1, r = 0;
        while (i > 0)
        {
            f /= base;
            r += f*(i % base);
            i /= base;
        }
        return r;
    };
    DynamicList<vector> pts(64);
    for (label i = 1; pts.size() < 32; ++i)
    {
        const vector x
        (
            2*halton(i, 2) - 1, 2*halton(i, 3) - 1, 2*halton(i, 5) - 1
        );
        if (magSqr(x) <= 1)
        {
            pts.append(x);
        }
    }
    for (label i = 0; i < 32; ++i)
    {
        pts.append(-pts[i]);
    }
    unitPoints_.transfer(pts);
}


void Foam::demCoupling::voidFractionModels::divided::distribute
(
    const particleData& particles,
    const particleCombine& combine
)
{
    const boundBox localBounds(meshReachBox(mesh_));

    // Points per cell (a particle touches few cells: linear search)
    DynamicList<label> cells(8);
    DynamicList<scalar> counts(8);

    forAll(particles.position, i)
    {
        const label host = particles.cell[i];
        if (particles.hostProc[i] < 0)
        {
            continue;   // outside the whole mesh: no volume, no force
        }

        const scalar r = 0.5*particles.diameter[i];
        const point& x0 = particles.position[i];

        // Another processor's particle: only if it (or one of its
        // periodic images) reaches this mesh
        if
        (
            host < 0
         && !sphereReaches(localBounds, x0, r, periodic_.shifts())
        )
        {
            continue;
        }

        cells.clear();
        counts.clear();
        for (const vector& u : unitPoints_)
        {
            const point x(x0 + r*u);
            label c = -1;
            if (host >= 0 || localBounds.contains(x))
            {
                c = particleLocator::findCellNear(mesh_, x, host);
            }
            // Beyond a cyclic patch (outside the whole mesh's box: a point
            // on the patch itself belongs to this side): the point's
            // periodic image
            for
            (
                label k = 0;
                c < 0 && k < periodic_.shifts().size() && periodic_.outside(x);
                ++k
            )
            {
                const point xImage(x + periodic_.shifts()[k]);
                if (localBounds.contains(xImage))
                {
                    c = particleLocator::findCellNear(mesh_, xImage, -1);
                }
            }
            if (c < 0)
            {
                continue;
            }
            const label k = cells.find(c);
            if (k < 0)
            {
                cells.append(c);
                counts.append(1);
            }
            else
            {
                counts[k] += 1;
            }
        }

        if (host >= 0 && cells.empty())
        {
            // Every point on other processors: keep a share on the host
            cells.append(host);
            counts.append(1);
        }

        forAll(cells, k)
        {
            addCell(i, cells[k], counts[k]);
        }
    }

    // A point outside every processor's mesh (beyond a wall; beyond a
    // cyclic patch it lands on the periodic image) is left out
    normaliseWeights(particles, combine);
}


// ************************************************************************* //
