// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "particleExchange.H"
#include "inputCheck.H"
#include "couplingKeywords.H"
#include "Pstream.H"

namespace Foam
{
namespace demCoupling
{
    defineTypeNameAndDebug(particleExchange, 0);
    defineRunTimeSelectionTable(particleExchange, dictionary);
}
}

namespace
{
    // The keyword of couplingProperties this family reads
    const Foam::demCoupling::couplingKeywords::declare keywords({"exchange"});
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCoupling::particleExchange::particleExchange()
:
    nTotal_(0),
    seconds_(0),
    clock_(),
    countsTraffic_(false),
    messagesSent_(0),
    bytesSent_(0),
    nDistributed_(0)
{}


// * * * * * * * * * * * * * * * * Selector  * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::demCoupling::particleExchange>
Foam::demCoupling::particleExchange::New
(
    const dictionary& dict,
    const fvMesh& mesh
)
{
    const word exchangeType
    (
        dict.getOrDefault<word>("exchange", "manyToMany")
    );

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(exchangeType);

    if (!cstrIter.found())
    {
        inputCheck::unknownModel
        (
            dict, "exchange", exchangeType,
            dictionaryConstructorTablePtr_->sortedToc()
        );
    }

    if (Pstream::parRun())
    {
        Info<< "Particle exchange between ranks: " << exchangeType << endl;
    }

    return autoPtr<particleExchange>(cstrIter()(dict, mesh));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::demCoupling::particleExchange::pack
(
    const particleData& p,
    const label i,
    double* s
)
{
    s[0] = p.tag[i];
    s[1] = p.type[i];
    for (direction k = 0; k < 3; ++k)
    {
        s[2 + k] = p.position[i][k];
        s[5 + k] = p.velocity[i][k];
        s[8 + k] = p.omega[i][k];
    }
    s[11] = p.diameter[i];
    s[12] = p.density[i];
    for (direction k = 0; k < 3; ++k)
    {
        s[13 + k] = p.meanVelocity[i][k];
        s[17 + k] = p.demUf[i][k];
    }
    s[16] = p.demK[i];
}


void Foam::demCoupling::particleExchange::unpack
(
    const double* s,
    particleData& p,
    const label i
)
{
    p.tag[i] = label(s[0]);
    p.type[i] = label(s[1]);
    p.position[i] = vector(s[2], s[3], s[4]);
    p.velocity[i] = vector(s[5], s[6], s[7]);
    p.omega[i] = vector(s[8], s[9], s[10]);
    p.diameter[i] = s[11];
    p.density[i] = s[12];
    p.meanVelocity[i] = vector(s[13], s[14], s[15]);
    p.demK[i] = s[16];
    p.demUf[i] = vector(s[17], s[18], s[19]);
    p.cell[i] = -1;
    p.hostProc[i] = -1;
}


void Foam::demCoupling::particleExchange::copyOwned
(
    const particleData& owned,
    particleData& particles
)
{
    particles = owned;
    nTotal_ = owned.size();
}


void Foam::demCoupling::particleExchange::printTraffic() const
{
    if (!Pstream::parRun() || !countsTraffic_)
    {
        return;
    }
    const scalar steps = max(nDistributed_, label(1));
    const scalar messages = messagesSent_/steps;
    const scalar kB = bytesSent_/steps/1024;
    Info<< "Exchange traffic per rank and coupling step (to other ranks): "
        << "messages min " << returnReduce(messages, minOp<scalar>())
        << ", max " << returnReduce(messages, maxOp<scalar>())
        << "; kB min " << returnReduce(kB, minOp<scalar>())
        << ", max " << returnReduce(kB, maxOp<scalar>())
        << " (" << Pstream::nProcs() << " ranks)" << endl;
}


Foam::List<Foam::vector> Foam::demCoupling::particleExchange::toOwners
(
    const List<vector>& values
) const
{
    if (!Pstream::parRun())
    {
        return values;
    }
    scalarList flat(3*values.size());
    forAll(values, i)
    {
        for (direction k = 0; k < 3; ++k)
        {
            flat[3*i + k] = values[i][k];
        }
    }
    const scalarList owned(toOwners(flat, 3));
    List<vector> result(owned.size()/3);
    forAll(result, i)
    {
        result[i] = vector(owned[3*i], owned[3*i + 1], owned[3*i + 2]);
    }
    return result;
}


// ************************************************************************* //
