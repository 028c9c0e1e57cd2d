#include "particleLocator.H"
#include "Pstream.H"
#include "ops.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCoupling::particleLocator::particleLocator(const fvMesh& mesh)
:
    mesh_(mesh),
    bounds_(mesh.points(), false),
    lastCell_(),
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

    // One host per particle: the lowest rank that found it
    const label nProcs = Pstream::nProcs();
    labelList host(n, nProcs);
    forAll(host, i)
    {
        if (particles.cell[i] >= 0)
        {
            host[i] = Pstream::myProcNo();
        }
    }
    if (Pstream::parRun())
    {
        Pstream::listCombineGather(host, minEqOp<label>());
        Pstream::listCombineScatter(host);
    }

    lost_ = 0;
    forAll(host, i)
    {
        if (host[i] == nProcs)
        {
            ++lost_;
            particles.hostProc[i] = -1;
        }
        else
        {
            particles.hostProc[i] = host[i];
        }
        if (host[i] != Pstream::myProcNo())
        {
            particles.cell[i] = -1;
        }
        else
        {
            nextCell.insert(particles.tag[i], particles.cell[i]);
        }
    }
    lastCell_.transfer(nextCell);
}


// ************************************************************************* //
