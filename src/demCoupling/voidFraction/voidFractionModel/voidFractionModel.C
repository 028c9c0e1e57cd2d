#include "voidFractionModel.H"

namespace Foam
{
namespace demCoupling
{
    defineTypeNameAndDebug(voidFractionModel, 0);
    defineRunTimeSelectionTable(voidFractionModel, dictionary);
}
}


Foam::demCoupling::voidFractionModel::voidFractionModel
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    mesh_(mesh),
    minVoidFraction_
    (
        getAllowed<scalar>
        (
            dict, "minVoidFraction",
            [](const scalar v) { return v > 0 && v < 1; },
            "> 0 and < 1 (the smallest fluid fraction a cell keeps)"
        )
    ),
    cells_(),
    weights_(),
    floorHits_(0),
    totalFloorHits_(0)
{}


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
        FatalIOErrorInLookup
        (
            dict,
            "voidFraction",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    Info<< "Selecting void-fraction model " << modelType << endl;

    return autoPtr<voidFractionModel>(cstrIter()(dict, mesh));
}


void Foam::demCoupling::voidFractionModel::normaliseWeights
(
    const particleData& particles
)
{
    scalarList total(weights_.size(), Zero);
    forAll(weights_, i)
    {
        for (const scalar w : weights_[i]) { total[i] += w; }
    }
    particles.combine(total, 1, combineOp::sum);
    forAll(weights_, i)
    {
        if (total[i] > 0)
        {
            for (scalar& w : weights_[i])
            {
                w /= total[i];
            }
        }
    }
}


void Foam::demCoupling::voidFractionModel::update
(
    const particleData& particles,
    volScalarField& eps
)
{
    cells_.setSize(particles.size());
    weights_.setSize(particles.size());
    distribute(particles);

    scalarList Vp(particles.size());
    forAll(Vp, i)
    {
        Vp[i] = particles.volume(i);
    }
    const scalarField solid(spread(Vp));

    floorHits_ = 0;
    scalarField& epsI = eps.primitiveFieldRef();
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
    totalFloorHits_ += floorHits_;

    eps.correctBoundaryConditions();
}
