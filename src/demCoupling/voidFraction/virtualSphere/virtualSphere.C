// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "virtualSphere.H"
#include "meshReach.H"
#include "addToRunTimeSelectionTable.H"
#include "gravityMeshObject.H"

namespace Foam
{
namespace demCoupling
{
namespace voidFractionModels
{
    defineTypeNameAndDebug(virtualSphere, 0);
    addToRunTimeSelectionTable(voidFractionModel, virtualSphere, dictionary);
}
}
}


Foam::demCoupling::voidFractionModels::virtualSphere::virtualSphere
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    voidFractionModel(dict, mesh),
    diameterRatio_
    (
        inputCheck::get<scalar>
        (
            inputCheck::subDict
            (
                dict, "virtualSphereCoeffs",
                {"diameterRatio", "sizeThreshold", "verticalDiameterRatio"}
            ),
            "diameterRatio",
            [](const scalar k) { return k >= 1; },
            ">= 1 (virtual-sphere diameter / particle diameter; seed: 4)"
        )
    ),
    sizeThreshold_
    (
        inputCheck::get<scalar>
        (
            dict.subDict("virtualSphereCoeffs"), "sizeThreshold",
            [](const scalar c) { return c > 0; },
            "> 0 (particles with d > sizeThreshold dx use the virtual"
            " sphere; seed: 0.25)"
        )
    ),
    verticalRatio_(diameterRatio_),
    up_(0, 0, 1),
    binOrigin_(Zero),
    binSize_(1),
    binStart_(),
    binCells_(),
    sphereCells_()
{
    const dictionary& coeffs = dict.subDict("virtualSphereCoeffs");
    verticalRatio_ = inputCheck::getOrDefault<scalar>
    (
        coeffs, "verticalDiameterRatio", diameterRatio_,
        [&](const scalar kv) { return kv >= 1 && kv <= diameterRatio_; },
        "between 1 and diameterRatio (" + Foam::name(diameterRatio_)
      + "): the spheroid's diameter along gravity / d (default"
        " diameterRatio, the sphere)"
    );
    Info<< "    virtual sphere: diameter " << diameterRatio_ << " d for"
        << " particles with d > " << sizeThreshold_ << " dx" << endl;
    if (verticalRatio_ < diameterRatio_)
    {
        const vector g(meshObjects::gravity::New(mesh.time()).value());
        if (mag(g) < SMALL)
        {
            FatalIOErrorInFunction(coeffs)
                << "verticalDiameterRatio in " << coeffs.name()
                << " needs gravity (constant/g, not zero): the spheroid's"
                << " short axis is along it" << exit(FatalIOError);
        }
        up_ = -g/mag(g);
        Info<< "    an oblate spheroid: " << verticalRatio_ << " d along"
            << " gravity (verticalDiameterRatio)" << endl;
    }

    // Bins of the cell centres: a uniform grid over the mesh's bounds
    // with about one centre per bin (a sphere query visits the few bins
    // its box overlaps; no tree walk, no allocation)
    const pointField& C = mesh.C().primitiveField();
    const label nCells = C.size();
    boundBox bb(mesh.points(), false);
    if (nCells == 0 || bb.empty())
    {
        bb = boundBox(point::zero, point::one);
    }
    binOrigin_ = bb.min();
    const vector span(max(bb.span(), vector::uniform(VSMALL)));
    scalar h = cbrt(cmptProduct(span)/max(nCells, label(1)));
    for (direction k = 0; k < 3; ++k)
    {
        h = min(max(h, span[k]/1000), GREAT);
    }
    binSize_ = h;
    label nTotal = 1;
    for (direction k = 0; k < 3; ++k)
    {
        nBins_[k] = max(label(1), label(std::ceil(span[k]/h)));
        nTotal *= nBins_[k];
    }
    binStart_.setSize(nTotal + 1, Zero);
    labelList binOfCell(nCells);
    forAll(C, c)
    {
        binOfCell[c] =
            binOf(C[c].x(), 0)
          + nBins_[0]*(binOf(C[c].y(), 1) + nBins_[1]*binOf(C[c].z(), 2));
        ++binStart_[binOfCell[c] + 1];
    }
    for (label b = 0; b < nTotal; ++b)
    {
        binStart_[b + 1] += binStart_[b];
    }
    binCells_.setSize(nCells);
    labelList fill(SubList<label>(binStart_, nTotal));
    forAll(C, c)
    {
        binCells_[fill[binOfCell[c]]++] = c;
    }
}


void Foam::demCoupling::voidFractionModels::virtualSphere::distribute
(
    const particleData& particles,
    const particleCombine& combine
)
{
    const label n = particles.size();
    const scalarField& V = mesh_.V();
    const volVectorField& C = mesh_.C();
    DynamicList<label>& cells = sphereCells_;

    // The host decides whether a particle is spread; all processors learn it
    // (d > c dx with dx = cbrt(V), in cubes: no cube root per particle)
    labelList spread(n, Zero);
    const scalar threshold3 = pow3(sizeThreshold_);
    forAll(particles.cell, i)
    {
        const label host = particles.cell[i];
        if (host >= 0 && pow3(particles.diameter[i]) > threshold3*V[host])
        {
            spread[i] = 1;
        }
    }
    combine.combine(spread, combineOp::max);

    const boundBox localBounds(meshReachBox(mesh_));

    // The spheroid: |r|^2 + (k^2/k_v^2 - 1) (r.up)^2 <= R^2 (0: the sphere)
    const scalar flatten = sqr(diameterRatio_/verticalRatio_) - 1;

    forAll(particles.position, i)
    {
        const label host = particles.cell[i];
        if (particles.hostProc[i] < 0)
        {
            continue;   // outside the whole mesh: no volume, no force
        }

        if (!spread[i])
        {
            if (host >= 0)
            {
                addCell(i, host, 1.0);
            }
            continue;
        }

        const point& x0 = particles.position[i];
        const scalar R = 0.5*diameterRatio_*particles.diameter[i];
        const scalar R2 = sqr(R);

        // Cells whose centre is inside the sphere around x (bins of cell
        // centres that the sphere's box overlaps, filtered exactly); the
        // host always. An image of the sphere (across cyclic patches) may
        // reach cells the sphere itself reached: those are taken once.
        cells.clear();
        bool haveHost = false;
        const auto collect = [&](const point& x, const bool image)
        {
            if (!sphereReaches(localBounds, x, R, List<vector>()))
            {
                return;
            }
            label lo[3], hi[3];
            for (direction k = 0; k < 3; ++k)
            {
                lo[k] = binOf(x[k] - R, k);
                hi[k] = binOf(x[k] + R, k);
            }
            for (label bz = lo[2]; bz <= hi[2]; ++bz)
            {
                for (label by = lo[1]; by <= hi[1]; ++by)
                {
                    const label row = nBins_[0]*(by + nBins_[1]*bz);
                    for (label bx = lo[0]; bx <= hi[0]; ++bx)
                    {
                        const label bin = row + bx;
                        for
                        (
                            label j = binStart_[bin];
                            j < binStart_[bin + 1];
                            ++j
                        )
                        {
                            const label c = binCells_[j];
                            if
                            (
                                (
                                    c == host
                                 || (
                                        flatten > 0
                                      ? magSqr(C[c] - x)
                                      + flatten*sqr((C[c] - x) & up_)
                                      : magSqr(C[c] - x)
                                    ) <= R2
                                )
                             && (!image || cells.find(c) < 0)
                            )
                            {
                                cells.append(c);
                                haveHost = haveHost || c == host;
                            }
                        }
                    }
                }
            }
        };
        collect(x0, false);
        for (const vector& shift : periodic_.shifts())
        {
            collect(x0 + shift, true);
        }
        if (host >= 0 && !haveHost)
        {
            cells.append(host);
        }
        for (const label c : cells)
        {
            addCell(i, c, V[c]);
        }
    }

    // Weights V_c / V_VS, V_VS summed over processors
    normaliseWeights(particles, combine);
}


// ************************************************************************* //
