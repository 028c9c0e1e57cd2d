#include "virtualSphere.H"
#include "addToRunTimeSelectionTable.H"
#include "treeDataCell.H"
#include "indexedOctree.H"

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
        getAllowed<scalar>
        (
            dict.subDict("virtualSphereCoeffs"), "diameterRatio",
            [](const scalar k) { return k >= 1; },
            ">= 1 (virtual-sphere diameter / particle diameter; seed: 4)"
        )
    ),
    sizeThreshold_
    (
        getAllowed<scalar>
        (
            dict.subDict("virtualSphereCoeffs"), "sizeThreshold",
            [](const scalar c) { return c > 0; },
            "> 0 (particles with d > sizeThreshold dx use the virtual"
            " sphere; seed: 0.25)"
        )
    ),
    nSpread_(0),
    centres_(mesh.C().primitiveField()),
    centreTree_()
{
    Info<< "    virtual sphere: diameter " << diameterRatio_ << " d for"
        << " particles with d > " << sizeThreshold_ << " dx" << endl;

    treeBoundBox bb(centres_);
    bb.min() -= vector::uniform(1e-6*mag(bb.span()) + VSMALL);
    bb.max() += vector::uniform(1e-6*mag(bb.span()) + VSMALL);
    centreTree_.reset
    (
        new indexedOctree<treeDataPoint>(treeDataPoint(centres_), bb, 8, 10, 3.0)
    );
}


void Foam::demCoupling::voidFractionModels::virtualSphere::distribute
(
    const particleData& particles
)
{
    const label n = particles.size();
    const scalarField& V = mesh_.V();
    const volVectorField& C = mesh_.C();

    // The host decides whether a particle is spread; all processors learn it
    labelList spread(n, Zero);
    forAll(particles.cell, i)
    {
        const label host = particles.cell[i];
        if (host >= 0 && particles.diameter[i] > sizeThreshold_*cbrt(V[host]))
        {
            spread[i] = 1;
        }
    }
    particles.combine(spread, combineOp::max);

    boundBox localBounds(mesh_.points(), false);
    nSpread_ = 0;

    forAll(particles.position, i)
    {
        const label host = particles.cell[i];
        cells_[i].clear();
        weights_[i].clear();
        if (particles.hostProc[i] < 0)
        {
            continue;   // outside the whole mesh: no volume, no force
        }

        if (!spread[i])
        {
            if (host >= 0)
            {
                cells_[i] = labelList(1, host);
                weights_[i] = scalarList(1, 1.0);
            }
            continue;
        }
        ++nSpread_;

        const point& x0 = particles.position[i];
        const scalar R = 0.5*diameterRatio_*particles.diameter[i];
        if
        (
            host < 0
         && !localBounds.overlaps
            (
                boundBox(x0 - vector::uniform(R), x0 + vector::uniform(R))
            )
        )
        {
            continue;
        }

        // Cells whose centre is inside the sphere (the octree's candidates,
        // from a slightly larger sphere, filtered exactly); the host always
        const labelList candidates
        (
            centreTree_->findSphere(x0, sqr(R)*(1 + 1e-9))
        );
        DynamicList<label> cells(candidates.size() + 1);
        DynamicList<scalar> w(candidates.size() + 1);
        for (const label c : candidates)
        {
            if (c == host || magSqr(C[c] - x0) <= sqr(R))
            {
                cells.append(c);
                w.append(V[c]);
            }
        }
        if (host >= 0 && !cells.found(host))
        {
            cells.append(host);
            w.append(V[host]);
        }
        cells_[i].transfer(cells);
        weights_[i].transfer(w);
    }

    reduce(nSpread_, maxOp<label>());

    // Weights V_c / V_VS, V_VS summed over processors
    normaliseWeights(particles);
}


// ************************************************************************* //
