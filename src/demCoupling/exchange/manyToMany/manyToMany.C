// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "manyToMany.H"
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
    defineTypeNameAndDebug(manyToMany, 0);
    addToRunTimeSelectionTable(particleExchange, manyToMany, dictionary);
}
}
}


namespace
{
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
    nOwned_(0)
{
    if (!Pstream::parRun())
    {
        return;
    }
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
        mine, 12, MPI_DOUBLE, all.data(), 12, MPI_DOUBLE, solverComm()
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


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

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

    scalarList received(recvAt.last() + recvN.last());
    MPI_Alltoallv
    (
        values.cdata(), sendN.cdata(), sendAt.cdata(), MPI_DOUBLE,
        received.data(), recvN.cdata(), recvAt.cdata(), MPI_DOUBLE,
        solverComm()
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
    forAll(dest, r)
    {
        sendIndices_[r].transfer(dest[r]);
        sendCounts_[r] = sendIndices_[r].size();
    }
    recvCounts_.setSize(nRanks);
    MPI_Alltoall
    (
        sendCounts_.cdata(), 1, MPI_INT, recvCounts_.data(), 1, MPI_INT,
        solverComm()
    );
    recvOffsets_ = blockOffsets(recvCounts_, 1);
    const label nHeld = recvOffsets_.last() + recvCounts_.last();

    const List<int> sendN(times(sendCounts_, nPacked));
    const List<int> sendAt(blockOffsets(sendCounts_, nPacked));
    const List<int> recvN(times(recvCounts_, nPacked));
    const List<int> recvAt(blockOffsets(recvCounts_, nPacked));

    std::vector<double> send(sendAt.last() + sendN.last());
    {
        double* s = send.data();
        for (const labelList& indices : sendIndices_)
        {
            for (const label i : indices)
            {
                pack(owned, i, s);
                s += nPacked;
            }
        }
    }
    std::vector<double> received(nPacked*nHeld);
    MPI_Alltoallv
    (
        send.data(), sendN.cdata(), sendAt.cdata(), MPI_DOUBLE,
        received.data(), recvN.cdata(), recvAt.cdata(), MPI_DOUBLE,
        solverComm()
    );

    particles.resize(nHeld);
    for (label i = 0; i < nHeld; ++i)
    {
        unpack(&received[nPacked*i], particles, i);
    }

    int n = nOwned_, total = 0;
    MPI_Allreduce(&n, &total, 1, MPI_INT, MPI_SUM, solverComm());
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
    MPI_Alltoallv
    (
        send.cdata(), sendN.cdata(), sendAt.cdata(), MPI_DOUBLE,
        values.data(), recvN.cdata(), recvAt.cdata(), MPI_DOUBLE,
        solverComm()
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
