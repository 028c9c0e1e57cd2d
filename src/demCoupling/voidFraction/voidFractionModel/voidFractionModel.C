// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "voidFractionModel.H"
#include "couplingKeywords.H"

namespace Foam
{
namespace demCoupling
{
    defineTypeNameAndDebug(voidFractionModel, 0);
    defineRunTimeSelectionTable(voidFractionModel, dictionary);
}
}

namespace
{
    // The keywords of couplingProperties this family reads
    const Foam::demCoupling::couplingKeywords::declare keywords
    (
        {"voidFraction", "minVoidFraction", "voidFractionFloor"},
        &Foam::demCoupling::voidFractionModel::modelNames
    );
}


const Foam::Enum
<
    Foam::demCoupling::voidFractionModel::floorTreatment
>
Foam::demCoupling::voidFractionModel::floorTreatmentNames
({
    {floorTreatment::clip, "clip"},
    {floorTreatment::spill, "spill"},
});


Foam::demCoupling::voidFractionModel::voidFractionModel
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    mesh_(mesh),
    periodic_(mesh),
    minVoidFraction_
    (
        inputCheck::get<scalar>
        (
            dict, "minVoidFraction",
            [](const scalar v) { return v > 0 && v < 1; },
            "> 0 and < 1 (the smallest fluid fraction a cell keeps)"
        )
    ),
    cellStart_(1, Zero),
    cellList_(),
    weightList_(),
    lastAdded_(-1),
    floorHits_(0),
    totalFloorHits_(0),
    spill_(),
    spilledCells_(0),
    totalSpilledCells_(0)
{
    const floorTreatment floor = inputCheck::selectOrDefault
    (
        dict, "voidFractionFloor", floorTreatmentNames,
        floorTreatment::clip,
        "clip (eps set to minVoidFraction, the solid beyond it lost to"
        " the mixture) and spill (the solid beyond it moved to the"
        " neighbouring cells, conserved)"
    );
    if (floor == floorTreatment::spill)
    {
        spill_.reset(new solidSpill(mesh_, 1 - minVoidFraction_));
    }
}


Foam::autoPtr<Foam::demCoupling::voidFractionModel>
Foam::demCoupling::voidFractionModel::New
(
    const dictionary& dict,
    const fvMesh& mesh
)
{
    const word modelType(dict.get<word>("voidFraction"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        inputCheck::unknownModel(dict, "voidFraction", modelType, modelNames());
    }

    Info<< "Selecting void-fraction model " << modelType << endl;

    return autoPtr<voidFractionModel>(cstrIter()(dict, mesh));
}


Foam::wordList Foam::demCoupling::voidFractionModel::modelNames()
{
    return dictionaryConstructorTablePtr_->sortedToc();
}


void Foam::demCoupling::voidFractionModel::normaliseWeights
(
    const particleData& particles,
    const particleCombine& combine
)
{
    closeCells();
    const label n = cellStart_.size() - 1;
    scalarList total(n, Zero);
    for (label i = 0; i < n; ++i)
    {
        for (label k = cellStart_[i]; k < cellStart_[i + 1]; ++k)
        {
            total[i] += weightList_[k];
        }
    }
    combine.combine(total, 1, combineOp::sum);
    for (label i = 0; i < n; ++i)
    {
        if (total[i] > 0)
        {
            for (label k = cellStart_[i]; k < cellStart_[i + 1]; ++k)
            {
                weightList_[k] /= total[i];
            }
        }
    }
}


void Foam::demCoupling::voidFractionModel::closeCells()
{
    while (lastAdded_ + 1 < cellStart_.size())
    {
        cellStart_[++lastAdded_] = cellList_.size();
    }
}


void Foam::demCoupling::voidFractionModel::update
(
    const particleData& particles,
    const particleCombine& combine,
    volScalarField& eps
)
{
    cellStart_.setSize(particles.size() + 1);
    cellStart_[0] = 0;
    cellList_.clear();
    weightList_.clear();
    lastAdded_ = 0;     // particle 0 starts at 0
    distribute(particles, combine);
    closeCells();

    scalarList Vp(particles.size());
    forAll(Vp, i)
    {
        Vp[i] = particles.volume(i);
    }
    scalarField solid(spread(Vp));

    scalarField& epsI = eps.primitiveFieldRef();
    floorHits_ = 0;
    if (spill_)
    {
        floorHits_ = spill_->spill(solid, spilledCells_);
        totalSpilledCells_ += spilledCells_;
        forAll(epsI, c)
        {
            epsI[c] = max(1 - solid[c], minVoidFraction_);
        }
    }
    else
    {
        forAll(epsI, c)
        {
            epsI[c] = 1 - solid[c];
            if (epsI[c] < minVoidFraction_)
            {
                epsI[c] = minVoidFraction_;
                ++floorHits_;
            }
        }
        reduce(floorHits_, sumOp<label>());
    }
    totalFloorHits_ += floorHits_;

    eps.correctBoundaryConditions();
}
