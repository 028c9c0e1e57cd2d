// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "allReduce.H"
#include "meshReach.H"
#include "addToRunTimeSelectionTable.H"
#include "Pstream.H"
#include <mpi.h>

namespace Foam
{
namespace demCoupling
{
namespace particleExchanges
{
    defineTypeNameAndDebug(allReduce, 0);
    addToRunTimeSelectionTable(particleExchange, allReduce, dictionary);
}
}
}


namespace
{
    MPI_Op mpiOp(const Foam::demCoupling::combineOp op)
    {
        using Foam::demCoupling::combineOp;
        return op == combineOp::sum ? MPI_SUM
             : op == combineOp::min ? MPI_MIN
             : MPI_MAX;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCoupling::particleExchanges::allReduce::allReduce
(
    const dictionary&,
    const fvMesh&
)
:
    particleExchange(),
    counts_(),
    offsets_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::demCoupling::particleExchanges::allReduce::distribute
(
    const particleData& owned,
    const scalar,
    const bool,
    particleData& particles
)
{
    timer t(*this);

    if (!Pstream::parRun())
    {
        copyOwned(owned, particles);
        counts_ = List<int>(1, owned.size());
        offsets_ = List<int>(1, 0);
        return;
    }

    const int nRanks = Pstream::nProcs();
    const int nOwned = owned.size();
    counts_.setSize(nRanks);
    offsets_.setSize(nRanks);
    MPI_Allgather
    (
        &nOwned, 1, MPI_INT, counts_.data(), 1, MPI_INT, solverComm()
    );

    int total = 0;
    List<int> valueCounts(nRanks), valueOffsets(nRanks);
    forAll(counts_, r)
    {
        offsets_[r] = total;
        valueCounts[r] = nPacked*counts_[r];
        valueOffsets[r] = nPacked*total;
        total += counts_[r];
    }

    std::vector<double> send(nPacked*nOwned), all(nPacked*total);
    for (int i = 0; i < nOwned; ++i)
    {
        pack(owned, i, &send[nPacked*i]);
    }
    MPI_Allgatherv
    (
        send.data(), nPacked*nOwned, MPI_DOUBLE,
        all.data(), valueCounts.data(), valueOffsets.data(), MPI_DOUBLE,
        solverComm()
    );

    particles.resize(total);
    for (int i = 0; i < total; ++i)
    {
        unpack(&all[nPacked*i], particles, i);
    }
    nTotal_ = total;
}


void Foam::demCoupling::particleExchanges::allReduce::combine
(
    scalarList& values,
    const label,
    const combineOp op
) const
{
    if (!Pstream::parRun() || values.empty())
    {
        return;
    }
    timer t(*this);
    const scalarList mine(values);
    MPI_Allreduce
    (
        mine.cdata(), values.data(), int(values.size()), MPI_DOUBLE,
        mpiOp(op), solverComm()
    );
}


Foam::scalarList Foam::demCoupling::particleExchanges::allReduce::toOwners
(
    const scalarList& values,
    const label width
) const
{
    if (!Pstream::parRun())
    {
        return values;
    }
    timer t(*this);

    scalarList summed(values.size());
    MPI_Allreduce
    (
        values.cdata(), summed.data(), int(values.size()), MPI_DOUBLE,
        MPI_SUM, solverComm()
    );
    const label me = Pstream::myProcNo();
    return scalarList
    (
        SubList<scalar>(summed, width*counts_[me], width*offsets_[me])
    );
}


// ************************************************************************* //
