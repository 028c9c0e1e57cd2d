// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "particleLocator.H"
#include "Pstream.H"
#include "ops.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCoupling::particleLocator::particleLocator(const fvMesh& mesh)
:
    mesh_(mesh),
    bounds_(mesh.points(), false),
    lastCell_(),
    lostTags_(),
    lost_(0),
    hintHits_(0),
    planarConvex_(mesh.nCells(), false)
{
    bounds_.inflate(1e-6);

    // Cells with planar faces and no point outside any face's plane: for
    // them "inside every face plane" is the same test as the tet one
    const vectorField& Sf = mesh.faceAreas();
    const vectorField& Cf = mesh.faceCentres();
    const pointField& pts = mesh.points();
    const labelListList& cellPoints = mesh.cellPoints();
    forAll(planarConvex_, c)
    {
        bool ok = true;
        for (const label f : mesh.cells()[c])
        {
            const scalar magS = mag(Sf[f]);
            const vector n((mesh.faceOwner()[f] == c ? 1 : -1)*Sf[f]/magS);
            const scalar tol = 1e-9*Foam::sqrt(magS);
            for (const label p : mesh.faces()[f])
            {
                ok = ok && mag((pts[p] - Cf[f]) & n) <= tol;
            }
            for (const label p : cellPoints[c])
            {
                ok = ok && ((pts[p] - Cf[f]) & n) <= tol;
            }
            if (!ok) break;
        }
        planarConvex_[c] = ok;
    }

    // The tet decomposition is built with a parallel synchronisation: build
    // it (and the cell octree) now, on every processor, not lazily on those
    // that happen to hold a particle (a deadlock otherwise)
    (void)mesh_.tetBasePtIs();
    (void)mesh_.cellTree();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

Foam::label Foam::demCoupling::particleLocator::findCell
(
    const point& p,
    const label hint
) const
{
    if (!bounds_.contains(p))
    {
        return -1;
    }
    if (hint >= 0 && hint < mesh_.nCells())
    {
        if (inCell(p, hint))
        {
            return hint;
        }
        for (const label nbr : mesh_.cellCells()[hint])
        {
            if (inCell(p, nbr))
            {
                return nbr;
            }
        }
    }
    return mesh_.findCell(p, polyMesh::CELL_TETS);
}


bool Foam::demCoupling::particleLocator::inCell
(
    const point& p,
    const label c
) const
{
    if (!planarConvex_[c])
    {
        return mesh_.pointInCell(p, c, polyMesh::CELL_TETS);
    }
    const vectorField& Sf = mesh_.faceAreas();
    const vectorField& Cf = mesh_.faceCentres();
    const labelList& owner = mesh_.faceOwner();
    for (const label f : mesh_.cells()[c])
    {
        const scalar d = (p - Cf[f]) & Sf[f];
        if (owner[f] == c ? d > 0 : d < 0)
        {
            return false;
        }
    }
    return true;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::label Foam::demCoupling::particleLocator::findCellNear
(
    const polyMesh& mesh,
    const point& p,
    const label hint
)
{
    if (hint >= 0 && hint < mesh.nCells())
    {
        if (mesh.pointInCell(p, hint, polyMesh::CELL_TETS))
        {
            return hint;
        }
        for (const label nbr : mesh.cellCells()[hint])
        {
            if (mesh.pointInCell(p, nbr, polyMesh::CELL_TETS))
            {
                return nbr;
            }
        }
    }
    return mesh.findCell(p, polyMesh::CELL_TETS);
}


void Foam::demCoupling::particleLocator::locate
(
    particleData& particles,
    const particleCombine& combine
)
{
    const label n = particles.size();
    hintHits_ = 0;

    // The hint list grows to the largest tag held (LIGGGHTS numbers its
    // atoms from 1 up); a tag far beyond the particle count (a run that
    // inserts and deletes for long) goes without a hint: found by search
    label maxTag = -1;
    for (const label tag : particles.tag)
    {
        maxTag = max(maxTag, tag);
    }
    const label maxHinted = 4*n + 65536;
    if (maxTag >= lastCell_.size() && lastCell_.size() <= maxHinted)
    {
        const label oldSize = lastCell_.size();
        lastCell_.setSize(min(max(maxTag + 1, 2*oldSize), maxHinted + 1));
        SubList<label>(lastCell_, lastCell_.size() - oldSize, oldSize) = -1;
    }
    auto hinted = [&](const label tag)
    {
        return tag >= 0 && tag < lastCell_.size();
    };

    // A particle new to this rank starts from the cell of the particle
    // before it: LIGGGHTS sorts its atoms in space, so that is near (the
    // first step of a run searched the octree for every particle)
    label previous = -1;
    forAll(particles.position, i)
    {
        const label tag = particles.tag[i];
        const label hint = hinted(tag) ? lastCell_[tag] : -1;
        const label c =
            findCell(particles.position[i], hint >= 0 ? hint : previous);
        particles.cell[i] = c;
        if (c >= 0)
        {
            previous = c;
            if (c == hint || (hint >= 0 && mesh_.cellCells()[hint].found(c)))
            {
                ++hintHits_;
            }
        }
    }

    // One host per particle: the lowest rank that found it. Ranks that
    // hold it without finding it offer nProcs + rank, so a particle no rank
    // finds comes out >= nProcs, and the lowest of its holders (the result
    // less nProcs) counts it: once, whichever exchange
    const label nProcs = Pstream::nProcs();
    const label me = Pstream::myProcNo();
    labelList host(n);
    forAll(host, i)
    {
        host[i] = particles.cell[i] >= 0 ? me : nProcs + me;
    }
    combine.combine(host, combineOp::min);

    DynamicList<label> lostTags;
    forAll(host, i)
    {
        if (host[i] >= nProcs)
        {
            particles.hostProc[i] = -1;
            if (host[i] - nProcs == me)
            {
                lostTags.append(particles.tag[i]);
            }
        }
        else
        {
            particles.hostProc[i] = host[i];
        }
        if (host[i] != me)
        {
            particles.cell[i] = -1;
        }
        if (hinted(particles.tag[i]))
        {
            lastCell_[particles.tag[i]] = particles.cell[i];
        }
    }
    lostTags_.transfer(lostTags);
    lost_ = returnReduce(lostTags_.size(), sumOp<label>());
}


// ************************************************************************* //
