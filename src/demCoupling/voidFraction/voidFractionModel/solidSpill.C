// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "solidSpill.H"
#include "syncTools.H"
#include "volFields.H"

Foam::demCoupling::solidSpill::solidSpill
(
    const fvMesh& mesh,
    const scalar maxSolidFraction,
    const label maxPasses
)
:
    mesh_(mesh),
    maxSolidFraction_(maxSolidFraction),
    maxPasses_(maxPasses),
    nNeighbours_(sumOverNeighbours(scalarField(mesh.nCells(), 1.0)))
{}


Foam::tmp<Foam::scalarField>
Foam::demCoupling::solidSpill::sumOverNeighbours(const scalarField& f) const
{
    auto tsum = tmp<scalarField>::New(mesh_.nCells(), Zero);
    scalarField& sum = tsum.ref();

    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    forAll(nei, facei)
    {
        sum[own[facei]] += f[nei[facei]];
        sum[nei[facei]] += f[own[facei]];
    }

    // The cell across each coupled boundary face (processor, cyclic)
    scalarField across;
    syncTools::swapBoundaryCellList(mesh_, f, across);
    const label start0 = mesh_.nInternalFaces();
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if (!pp.coupled())
        {
            continue;
        }
        const labelUList& fc = pp.faceCells();
        forAll(fc, i)
        {
            sum[fc[i]] += across[pp.start() + i - start0];
        }
    }
    return tsum;
}


Foam::label Foam::demCoupling::solidSpill::spill
(
    scalarField& solidFraction,
    label& spilledCells
) const
{
    const scalarField& V = mesh_.V();
    spilledCells = 0;

    // Each pass starts by counting the cells over the cap; the count after
    // the last pass is what is left over it
    for (label pass = 0; ; ++pass)
    {
        scalarField excess(V.size(), Zero);     // volume above the cap
        scalarField room(V.size(), Zero);       // volume below it
        label over = 0;
        forAll(V, c)
        {
            const scalar d = (solidFraction[c] - maxSolidFraction_)*V[c];
            if (d > tolerance_*V[c])
            {
                excess[c] = d;
                ++over;
            }
            else if (d < -tolerance_*V[c])
            {
                room[c] = -d;
            }
        }
        reduce(over, sumOp<label>());
        if (pass == 0)
        {
            spilledCells = over;
        }
        if (over == 0 || pass == maxPasses_)
        {
            return over;
        }

        // The share of its neighbours' room each over-full cell fills;
        // one whose neighbours are all full pushes its excess through
        // them, equally (they pass it on in the next pass)
        const scalarField R(sumOverNeighbours(room));
        scalarField share(V.size(), Zero);
        scalarField push(V.size(), Zero);
        forAll(V, c)
        {
            if (excess[c] > 0)
            {
                if (R[c] > 0)
                {
                    const scalar moved = min(excess[c], R[c]);
                    share[c] = moved/R[c];
                    solidFraction[c] -= moved/V[c];
                }
                else if (nNeighbours_[c] > 0)
                {
                    push[c] = excess[c]/nNeighbours_[c];
                    solidFraction[c] -= excess[c]/V[c];
                }
            }
        }
        const scalarField gainShare(sumOverNeighbours(share));
        const scalarField gainPush(sumOverNeighbours(push));
        forAll(V, c)
        {
            solidFraction[c] += (room[c]*gainShare[c] + gainPush[c])/V[c];
        }
    }
}
