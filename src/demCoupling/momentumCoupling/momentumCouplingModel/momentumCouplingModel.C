// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "momentumCouplingModel.H"
#include "inputCheck.H"
#include "couplingKeywords.H"

namespace Foam
{
namespace demCoupling
{
    defineTypeNameAndDebug(momentumCouplingModel, 0);
    defineRunTimeSelectionTable(momentumCouplingModel, dictionary);
}
}

namespace
{
    // The keyword of couplingProperties this family reads
    const Foam::demCoupling::couplingKeywords::declare keywords({"momentumCoupling"});
}


Foam::demCoupling::momentumCouplingModel::momentumCouplingModel
(
    const dictionary&,
    const fvMesh&
)
{}


Foam::autoPtr<Foam::demCoupling::momentumCouplingModel>
Foam::demCoupling::momentumCouplingModel::New
(
    const dictionary& dict,
    const fvMesh& mesh
)
{
    const word modelType(dict.get<word>("momentumCoupling"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        inputCheck::unknownModel
        (
            dict, "momentumCoupling", modelType,
            dictionaryConstructorTablePtr_->sortedToc()
        );
    }

    Info<< "Momentum coupling: " << modelType << endl;

    return autoPtr<momentumCouplingModel>(cstrIter()(dict, mesh));
}


Foam::tmp<Foam::vectorField>
Foam::demCoupling::momentumCouplingModel::volumeWeightedVelocity
(
    const particleData& particles,
    const voidFractionModel& voidFraction
) const
{
    const label n = particles.size();
    scalarList Vp(n);
    List<vector> VpUp(n);
    forAll(Vp, i)
    {
        Vp[i] = particles.volume(i);
        VpUp[i] = Vp[i]*particles.velocity[i];
    }
    const scalarField solid(voidFraction.spread(Vp));
    const vectorField momentum(voidFraction.spread(VpUp));

    auto tUs = tmp<vectorField>::New(solid.size(), Zero);
    vectorField& Us = tUs.ref();
    forAll(Us, c)
    {
        if (solid[c] > SMALL)
        {
            Us[c] = momentum[c]/solid[c];
        }
    }
    return tUs;
}


// ************************************************************************* //
