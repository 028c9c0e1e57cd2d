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
    hintHits_(0)
{
    bounds_.inflate(1e-6);

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
    return findCellNear(mesh_, p, hint);
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


void Foam::demCoupling::particleLocator::locate(particleData& particles)
{
    const label n = particles.size();
    hintHits_ = 0;

    Map<label> nextCell(2*n);
    forAll(particles.position, i)
    {
        const label hint = lastCell_.lookup(particles.tag[i], -1);
        const label c = findCell(particles.position[i], hint);
        particles.cell[i] = c;
        if (c >= 0)
        {
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
    particles.combine(host, combineOp::min);

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
        else
        {
            nextCell.insert(particles.tag[i], particles.cell[i]);
        }
    }
    lostTags_.transfer(lostTags);
    lost_ = returnReduce(lostTags_.size(), sumOp<label>());
    lastCell_.transfer(nextCell);
}


// ************************************************************************* //
