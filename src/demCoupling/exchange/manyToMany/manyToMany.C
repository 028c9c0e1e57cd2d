// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "manyToMany.H"
#include "meshReach.H"
#include "addToRunTimeSelectionTable.H"
#include "Pstream.H"
#include <mpi.h>
#include <algorithm>
#include <vector>

namespace Foam
{
namespace demCoupling
{
namespace particleExchanges
{
    defineTypeNameAndDebug(manyToMany, 0);
    addToRunTimeSelectionTable(particleExchange, manyToMany, dictionary);
}
}
}


namespace
{
    // Message tags on the exchange's own communicator
    constexpr int distributeTag = 1;
    constexpr int backTag = 2;
    constexpr int forwardTag = 3;

    // Displacements of consecutive blocks of counts[r]*width values
    Foam::List<int> blockOffsets(const Foam::List<int>& counts, const int width)
    {
        Foam::List<int> offsets(counts.size());
        int sum = 0;
        forAll(counts, r)
        {
            offsets[r] = sum;
            sum += width*counts[r];
        }
        return offsets;
    }

    Foam::List<int> times(const Foam::List<int>& counts, const int width)
    {
        Foam::List<int> result(counts.size());
        forAll(counts, r)
        {
            result[r] = width*counts[r];
        }
        return result;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCoupling::particleExchanges::manyToMany::manyToMany
(
    const dictionary&,
    const fvMesh& mesh
)
:
    particleExchange(),
    procBounds_(),
    centreBounds_(),
    periodic_(mesh),
    sendIndices_(),
    sendCounts_(),
    recvCounts_(),
    recvOffsets_(),
    nOwned_(0),
    sendTo_(),
    recvFrom_(),
    comm_(MPI_COMM_NULL)
{
    countsTraffic_ = true;
    if (!Pstream::parRun())
    {
        return;
    }
    MPI_Comm_dup(solverComm(), &comm_);
    // Every rank's mesh box and cell-centre box
    const boundBox local(meshReachBox(mesh));
    const boundBox centres(cellCentreReachBox(mesh));
    const double mine[12] =
    {
        local.min().x(), local.min().y(), local.min().z(),
        local.max().x(), local.max().y(), local.max().z(),
        centres.min().x(), centres.min().y(), centres.min().z(),
        centres.max().x(), centres.max().y(), centres.max().z()
    };
    const int nRanks = Pstream::nProcs();
    std::vector<double> all(12*nRanks);
    MPI_Allgather
    (
        mine, 12, MPI_DOUBLE, all.data(), 12, MPI_DOUBLE, comm_
    );
    procBounds_.setSize(nRanks);
    centreBounds_.setSize(nRanks);
    forAll(procBounds_, r)
    {
        const double* b = &all[12*r];
        procBounds_[r] =
            boundBox(point(b[0], b[1], b[2]), point(b[3], b[4], b[5]));
        centreBounds_[r] =
            boundBox(point(b[6], b[7], b[8]), point(b[9], b[10], b[11]));
    }
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * //

Foam::demCoupling::particleExchanges::manyToMany::~manyToMany()
{
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (comm_ != MPI_COMM_NULL && !finalized)
    {
        MPI_Comm_free(&comm_);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

void Foam::demCoupling::particleExchanges::manyToMany::exchangeBlocks
(
    const labelList& to,
    const double* send,
    const List<int>& sendN,
    const List<int>& sendAt,
    const labelList& from,
    double* received,
    const List<int>& recvN,
    const List<int>& recvAt,
    const int tag
) const
{
    const int me = Pstream::myProcNo();
    std::vector<MPI_Request> requests;
    requests.reserve(to.size() + from.size());
    for (const label r : from)
    {
        requests.emplace_back();
        MPI_Irecv
        (
            received + recvAt[r], recvN[r], MPI_DOUBLE, r, tag, comm_,
            &requests.back()
        );
    }
    for (const label r : to)
    {
        requests.emplace_back();
        MPI_Isend
        (
            send + sendAt[r], sendN[r], MPI_DOUBLE, r,
            tag, comm_, &requests.back()
        );
        ++messagesSent_;
        bytesSent_ += sizeof(double)*sendN[r];
    }
    std::copy
    (
        send + sendAt[me], send + sendAt[me] + sendN[me], received + recvAt[me]
    );
    MPI_Waitall(requests.size(), requests.data(), MPI_STATUSES_IGNORE);
}


Foam::scalarList
Foam::demCoupling::particleExchanges::manyToMany::backToOwners
(
    const scalarList& values,
    const label width,
    const combineOp op
) const
{
    // The held list is already in blocks by source rank
    const List<int> sendN(times(recvCounts_, width));
    const List<int> sendAt(blockOffsets(recvCounts_, width));
    const List<int> recvN(times(sendCounts_, width));
    const List<int> recvAt(blockOffsets(sendCounts_, width));

    // to the ranks this one received particles from, from those it sent
    // particles to
    scalarList received(recvAt.last() + recvN.last());
    exchangeBlocks
    (
        recvFrom_, values.cdata(), sendN, sendAt,
        sendTo_, received.data(), recvN, recvAt, backTag
    );

    scalarList owned(width*nOwned_, identity(op));
    forAll(sendIndices_, r)
    {
        const double* v = received.cdata() + recvAt[r];
        for (const label i : sendIndices_[r])
        {
            for (label k = 0; k < width; ++k)
            {
                owned[width*i + k] = apply(op, owned[width*i + k], *v++);
            }
        }
    }
    return owned;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::demCoupling::particleExchanges::manyToMany::distribute
(
    const particleData& owned,
    const scalar reachFactor,
    const bool toCellCentres,
    particleData& particles
)
{
    timer t(*this);

    if (!Pstream::parRun())
    {
        copyOwned(owned, particles);
        return;
    }

    const int nRanks = Pstream::nProcs();
    const int me = Pstream::myProcNo();
    nOwned_ = owned.size();

    // Where each owned particle is needed (a margin over the models' own
    // overlap tests, so that a rank never misses one it would use): where
    // its centre may lie, and where it reaches the mesh (or the cell
    // centres: half a cell less on every side of a rank's box)
    const List<boundBox>& reached = toCellCentres ? centreBounds_ : procBounds_;
    List<DynamicList<label>> dest(nRanks);
    for (label i = 0; i < nOwned_; ++i)
    {
        const point& x = owned.position[i];
        const scalar R = reachFactor*owned.diameter[i]*(1 + reachTolerance);
        const boundBox reach(x - vector::uniform(R), x + vector::uniform(R));
        bool sent = false;
        forAll(procBounds_, r)
        {
            bool needed =
                procBounds_[r].contains(x) || reached[r].overlaps(reach);
            for (const vector& s : periodic_.shifts())
            {
                needed = needed
                 || reached[r].overlaps
                    (
                        boundBox(reach.min() + s, reach.max() + s)
                    );
            }
            if (needed)
            {
                dest[r].append(i);
                sent = true;
            }
        }
        if (!sent)
        {
            dest[me].append(i);   // outside every mesh: its owner says so
        }
    }

    sendIndices_.setSize(nRanks);
    sendCounts_.setSize(nRanks);
    DynamicList<label> sendTo;
    forAll(dest, r)
    {
        sendIndices_[r].transfer(dest[r]);
        sendCounts_[r] = sendIndices_[r].size();
        if (r != me && sendCounts_[r] > 0)
        {
            sendTo.append(r);
        }
    }
    sendTo_.transfer(sendTo);
    ++nDistributed_;

    // Each partner's particles, packed
    List<std::vector<double>> send(nRanks);
    forAll(sendIndices_, r)
    {
        send[r].resize(nPacked*sendCounts_[r]);
        double* b = send[r].data();
        for (const label i : sendIndices_[r])
        {
            pack(owned, i, b);
            b += nPacked;
        }
    }

    // Sparse exchange without a count exchange (NBX): synchronous sends,
    // which complete only once received; receive whatever arrives; when
    // this rank's sends are all received, enter a non-blocking barrier;
    // once every rank has entered it, every message has been received
    List<std::vector<double>> received(nRanks);
    received[me].swap(send[me]);
    std::vector<MPI_Request> sends(sendTo_.size());
    forAll(sendTo_, k)
    {
        const label r = sendTo_[k];
        MPI_Issend
        (
            send[r].data(), send[r].size(), MPI_DOUBLE, r, distributeTag,
            comm_, &sends[k]
        );
        ++messagesSent_;
        bytesSent_ += sizeof(double)*send[r].size();
    }
    DynamicList<label> recvFrom;
    MPI_Request barrier = MPI_REQUEST_NULL;
    bool inBarrier = false;
    for (;;)
    {
        int arrived = 0;
        MPI_Status status;
        MPI_Iprobe(MPI_ANY_SOURCE, distributeTag, comm_, &arrived, &status);
        if (arrived)
        {
            int n = 0;
            MPI_Get_count(&status, MPI_DOUBLE, &n);
            const label r = status.MPI_SOURCE;
            received[r].resize(n);
            MPI_Recv
            (
                received[r].data(), n, MPI_DOUBLE, r, distributeTag, comm_,
                MPI_STATUS_IGNORE
            );
            recvFrom.append(r);
        }
        else if (inBarrier)
        {
            int done = 0;
            MPI_Test(&barrier, &done, MPI_STATUS_IGNORE);
            if (done)
            {
                break;
            }
        }
        else
        {
            int sent = 0;
            MPI_Testall(sends.size(), sends.data(), &sent, MPI_STATUSES_IGNORE);
            if (sent)
            {
                MPI_Ibarrier(comm_, &barrier);
                inBarrier = true;
            }
        }
    }
    Foam::sort(recvFrom);
    recvFrom_.transfer(recvFrom);

    // Held: the blocks in source-rank order
    recvCounts_.setSize(nRanks);
    forAll(received, r)
    {
        recvCounts_[r] = received[r].size()/nPacked;
    }
    recvOffsets_ = blockOffsets(recvCounts_, 1);
    const label nHeld = recvOffsets_.last() + recvCounts_.last();

    particles.resize(nHeld);
    forAll(received, r)
    {
        const double* b = received[r].data();
        for (label i = 0; i < recvCounts_[r]; ++i)
        {
            unpack(b, particles, recvOffsets_[r] + i);
            b += nPacked;
        }
    }

    int n = nOwned_, total = 0;
    MPI_Allreduce(&n, &total, 1, MPI_INT, MPI_SUM, comm_);
    nTotal_ = total;
}


void Foam::demCoupling::particleExchanges::manyToMany::combine
(
    scalarList& values,
    const label width,
    const combineOp op
) const
{
    if (!Pstream::parRun())
    {
        return;
    }
    timer t(*this);

    const scalarList owned(backToOwners(values, width, op));

    // and forward to every holder, as distribute() sent the particles
    const List<int> sendN(times(sendCounts_, width));
    const List<int> sendAt(blockOffsets(sendCounts_, width));
    const List<int> recvN(times(recvCounts_, width));
    const List<int> recvAt(blockOffsets(recvCounts_, width));

    scalarList send(sendAt.last() + sendN.last());
    {
        double* s = send.data();
        for (const labelList& indices : sendIndices_)
        {
            for (const label i : indices)
            {
                for (label k = 0; k < width; ++k)
                {
                    *s++ = owned[width*i + k];
                }
            }
        }
    }
    exchangeBlocks
    (
        sendTo_, send.cdata(), sendN, sendAt,
        recvFrom_, values.data(), recvN, recvAt, forwardTag
    );
}


Foam::scalarList Foam::demCoupling::particleExchanges::manyToMany::toOwners
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
    return backToOwners(values, width, combineOp::sum);
}



// ************************************************************************* //
