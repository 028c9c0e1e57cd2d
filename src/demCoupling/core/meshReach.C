// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "meshReach.H"
#include "Pstream.H"

MPI_Comm Foam::demCoupling::solverComm()
{
    return Pstream::parRun() ? MPI_COMM_WORLD : MPI_COMM_SELF;
}


Foam::boundBox Foam::demCoupling::meshReachBox(const fvMesh& mesh)
{
    boundBox box(mesh.points(), false);
    box.inflate(reachTolerance);
    return box;
}


Foam::boundBox Foam::demCoupling::cellCentreReachBox(const fvMesh& mesh)
{
    boundBox box(mesh.cellCentres(), false);
    if (box.empty())
    {
        box = boundBox(mesh.points(), false);
    }
    box.inflate(reachTolerance);
    return box;
}


bool Foam::demCoupling::sphereReaches
(
    const boundBox& box,
    const point& x,
    const scalar R,
    const List<vector>& shifts
)
{
    const vector r(vector::uniform(R));
    if (box.overlaps(boundBox(x - r, x + r)))
    {
        return true;
    }
    for (const vector& s : shifts)
    {
        if (box.overlaps(boundBox(x + s - r, x + s + r)))
        {
            return true;
        }
    }
    return false;
}
