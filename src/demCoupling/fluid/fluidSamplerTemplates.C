// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "fluidSampler.H"
#include "fvc.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

template<class Type, class AtHost>
void Foam::demCoupling::fluidSampler::sampleOnHost
(
    const particleData& particles,
    List<Type>& values,
    const AtHost& atHost
)
{
    forAll(values, i)
    {
        if (particles.hostProc[i] == Pstream::myProcNo())
        {
            values[i] = atHost(i);
        }
        else if (particles.hostProc[i] >= 0)
        {
            // Another processor hosts it and adds the value
            values[i] = Zero;
        }
        // else: no processor hosts it, the average stays
    }
}


template<class Type>
void Foam::demCoupling::fluidSampler::sampleAtHeight
(
    const GeometricField<Type, fvPatchField, volMesh>& fld,
    const GeometricField
    <
        typename outerProduct<vector, Type>::type, fvPatchField, volMesh
    >& gradFld,
    const particleData& particles,
    const scalar height,
    List<Type>& values
) const
{
    sampleOnHost
    (
        particles, values,
        [&](const label i)
        {
            return reconstructed
            (
                fld, gradFld, particles.cell[i],
                particles.position[i] + height*particles.diameter[i]*up_
            );
        }
    );
}


template<class Type>
void Foam::demCoupling::fluidSampler::sampleInCellAbove
(
    const GeometricField<Type, fvPatchField, volMesh>& fld,
    const particleData& particles,
    List<Type>& values
) const
{
    const PtrList<Field<Type>> across(valuesAcrossCoupledPatches(fld));
    sampleOnHost
    (
        particles, values,
        [&](const label i)
        {
            return valueInCellAbove(fld, across, particles.cell[i], up_);
        }
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
Foam::PtrList<Foam::Field<Type>>
Foam::demCoupling::fluidSampler::valuesAcrossCoupledPatches
(
    const GeometricField<Type, fvPatchField, volMesh>& fld
)
{
    PtrList<Field<Type>> across(fld.boundaryField().size());
    forAll(fld.boundaryField(), patchi)
    {
        const fvPatchField<Type>& fb = fld.boundaryField()[patchi];
        if (fb.coupled())
        {
            across.set(patchi, fb.patchNeighbourField().ptr());
        }
    }
    return across;
}


template<class Type>
Type Foam::demCoupling::fluidSampler::valueInCellAbove
(
    const GeometricField<Type, fvPatchField, volMesh>& fld,
    const PtrList<Field<Type>>& across,
    const label celli,
    const vector& up
)
{
    // A wall or an open boundary above: nothing arrives from beyond it
    return valueInCellAbove(fld, across, celli, up, fld[celli]);
}


template<class Type>
Type Foam::demCoupling::fluidSampler::valueInCellAbove
(
    const GeometricField<Type, fvPatchField, volMesh>& fld,
    const PtrList<Field<Type>>& across,
    const label celli,
    const vector& up,
    const Type& beyondBoundary
)
{
    const fvMesh& mesh = fld.mesh();
    const label upFace = faceAbove(mesh, celli, up);
    if (mesh.isInternalFace(upFace))
    {
        const label owner = mesh.faceOwner()[upFace];
        return fld[owner == celli ? mesh.faceNeighbour()[upFace] : owner];
    }
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    const label patchi = patches.whichPatch(upFace);
    if (across.set(patchi))
    {
        return across[patchi][upFace - patches[patchi].start()];
    }
    return beyondBoundary;
}


template<class Type>
Type Foam::demCoupling::fluidSampler::reconstructed
(
    const GeometricField<Type, fvPatchField, volMesh>& fld,
    const GeometricField
    <
        typename outerProduct<vector, Type>::type, fvPatchField, volMesh
    >& gradFld,
    const label celli,
    const point& p
)
{
    const fvMesh& mesh = fld.mesh();
    const Type f(fld[celli] + ((p - mesh.C()[celli]) & gradFld[celli]));

    // Bounds: the cell, its face neighbours and its boundary faces
    Type lo(fld[celli]);
    Type hi(fld[celli]);
    for (const label nbr : mesh.cellCells()[celli])
    {
        lo = min(lo, fld[nbr]);
        hi = max(hi, fld[nbr]);
    }
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    for (const label facei : mesh.cells()[celli])
    {
        if (mesh.isInternalFace(facei))
        {
            continue;
        }
        const label patchi = patches.whichPatch(facei);
        const fvPatchField<Type>& fb = fld.boundaryField()[patchi];
        if (fb.empty())
        {
            // An empty (2-D) patch has no values
            continue;
        }
        const Type& value = fb[facei - patches[patchi].start()];
        lo = min(lo, value);
        hi = max(hi, value);
    }
    return max(lo, min(hi, f));
}
