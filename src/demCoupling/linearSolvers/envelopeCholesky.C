// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "envelopeCholesky.H"
#include "bandCompression.H"
#include "error.H"
#include "cyclicLduInterface.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::demCoupling::envelopeCholesky::collectEntries
(
    const lduMatrix::solver& sol,
    scalarField& diag,
    labelList& cell0,
    labelList& cell1,
    scalarField& value
)
{
    const lduMatrix& matrix = sol.matrix();

    diag = matrix.diag();

    // One entry per internal face, then the cyclic face pairs
    DynamicList<label> entries0(matrix.lduAddr().lowerAddr());
    DynamicList<label> entries1(matrix.lduAddr().upperAddr());
    DynamicList<scalar> entryValues
    (
        matrix.hasUpper()
      ? matrix.upper()
      : scalarField(entries0.size(), Zero)
    );

    // Cyclic faces: A(i, j) = -bouCoeff (lduMatrix::Amul subtracts
    // bouCoeff times the neighbour's value), each pair once, from the
    // owner side
    const lduInterfaceFieldPtrsList& interfaces = sol.interfaces();
    forAll(interfaces, patchi)
    {
        if (!interfaces.set(patchi))
        {
            continue;
        }
        const lduInterface& face0 = interfaces[patchi].interface();
        if (!isA<cyclicLduInterface>(face0))
        {
            continue;
        }
        const cyclicLduInterface& cyclic =
            refCast<const cyclicLduInterface>(face0);
        if (!cyclic.owner())
        {
            continue;
        }
        const label nbrPatchi = cyclic.neighbPatchID();
        const labelUList& cells0 = face0.faceCells();
        const labelUList& cells1 =
            interfaces[nbrPatchi].interface().faceCells();
        const scalarField& coeffs = sol.interfaceBouCoeffs()[patchi];
        const scalarField& nbrCoeffs = sol.interfaceBouCoeffs()[nbrPatchi];
        forAll(cells0, facei)
        {
            if (cells0[facei] == cells1[facei])
            {
                // a cell coupled to itself (one cell across the cyclic):
                // both sides' faces act on its own value
                diag[cells0[facei]] -= coeffs[facei] + nbrCoeffs[facei];
            }
            else
            {
                entries0.append(cells0[facei]);
                entries1.append(cells1[facei]);
                entryValues.append(-coeffs[facei]);
            }
        }
    }

    cell0.transfer(entries0);
    cell1.transfer(entries1);
    value.transfer(entryValues);
}


void Foam::demCoupling::envelopeCholesky::layOut
(
    const scalar maxEntriesPerCell
)
{
    const label nCells = diag_.size();

    // Cell-to-cell connections of the matrix
    labelList nNeighbours(nCells, Zero);
    forAll(entryCell0_, entryi)
    {
        ++nNeighbours[entryCell0_[entryi]];
        ++nNeighbours[entryCell1_[entryi]];
    }
    labelListList cellCells(nCells);
    forAll(cellCells, celli)
    {
        cellCells[celli].setSize(nNeighbours[celli]);
        nNeighbours[celli] = 0;
    }
    forAll(entryCell0_, entryi)
    {
        const label l = entryCell0_[entryi];
        const label u = entryCell1_[entryi];
        cellCells[l][nNeighbours[l]++] = u;
        cellCells[u][nNeighbours[u]++] = l;
    }

    // Reverse Cuthill-McKee: a narrower envelope than Cuthill-McKee's
    orderedToCell_ = bandCompression(cellCells);
    reverse(orderedToCell_);
    cellToOrdered_.setSize(nCells);
    forAll(orderedToCell_, rowi)
    {
        cellToOrdered_[orderedToCell_[rowi]] = rowi;
    }

    firstColumn_ = identity(nCells);
    forAll(entryCell0_, entryi)
    {
        const label a = cellToOrdered_[entryCell0_[entryi]];
        const label b = cellToOrdered_[entryCell1_[entryi]];
        const label row = max(a, b);
        firstColumn_[row] = min(firstColumn_[row], min(a, b));
    }

    // The envelope's size before any of it is allocated (in doubles: it
    // may exceed a label)
    scalar nEntries = 0;
    for (label rowi = 0; rowi < nCells; ++rowi)
    {
        nEntries += rowi - firstColumn_[rowi];
    }
    if (nEntries > maxEntriesPerCell*max(nCells, label(1)))
    {
        FatalErrorInFunction
            << "system/fvSolution: solvers." << fieldName_ << ": the "
            << "envelopeCholesky preconditioner would keep " << nEntries
            << " entries for " << nCells << " cells ("
            << nEntries/max(nCells, label(1)) << " per cell), more than "
            << "maxEnvelopePerCell " << maxEntriesPerCell << ". Use "
            << "preconditioner DIC, or GAMG, for " << fieldName_ << ", or "
            << "raise the limit: preconditioner { preconditioner "
            << "envelopeCholesky; maxEnvelopePerCell <entries per cell>; }"
            << exit(FatalError);
    }

    rowStart_.setSize(nCells + 1);
    rowStart_[0] = 0;
    for (label rowi = 0; rowi < nCells; ++rowi)
    {
        rowStart_[rowi + 1] = rowStart_[rowi] + rowi - firstColumn_[rowi];
    }
}


void Foam::demCoupling::envelopeCholesky::factorise()
{
    const label nCells = diag_.size();

    lowerEntries_.setSize(rowStart_[nCells]);
    lowerEntries_ = 0;
    diagonal_.setSize(nCells);

    forAll(entryValue_, entryi)
    {
        const label a = cellToOrdered_[entryCell0_[entryi]];
        const label b = cellToOrdered_[entryCell1_[entryi]];
        const label row = max(a, b);
        const label column = min(a, b);
        lowerEntries_[rowStart_[row] + column - firstColumn_[row]] +=
            sign_*entryValue_[entryi];
    }
    forAll(diagonal_, rowi)
    {
        diagonal_[rowi] = sign_*diag_[orderedToCell_[rowi]];
    }

    // Row by row: L(i,j) = (B(i,j) - sum_k L(i,k) L(j,k))/L(j,j) for the
    // columns j of row i's envelope, then L(i,i) = sqrt(B(i,i) - sum L(i,k)^2)
    solveScalar* const __restrict__ entries = lowerEntries_.begin();
    for (label rowi = 0; rowi < nCells; ++rowi)
    {
        const label firsti = firstColumn_[rowi];
        solveScalar* const __restrict__ rowEntries =
            entries + rowStart_[rowi] - firsti;

        for (label columnj = firsti; columnj < rowi; ++columnj)
        {
            const label firstj = firstColumn_[columnj];
            const solveScalar* const __restrict__ columnEntries =
                entries + rowStart_[columnj] - firstj;

            solveScalar sum = rowEntries[columnj];
            for (label k = max(firsti, firstj); k < columnj; ++k)
            {
                sum -= rowEntries[k]*columnEntries[k];
            }
            rowEntries[columnj] = sum/diagonal_[columnj];
        }

        solveScalar pivot = diagonal_[rowi];
        for (label k = firsti; k < rowi; ++k)
        {
            pivot -= sqr(rowEntries[k]);
        }
        if (!(pivot > 0))
        {
            FatalErrorInFunction
                << "system/fvSolution: solvers." << fieldName_ << ": the "
                << "matrix of " << fieldName_ << " is not definite (pivot "
                << pivot << " in cell " << orderedToCell_[rowi] << "); the "
                << "envelopeCholesky preconditioner needs a symmetric "
                << "positive or negative definite matrix: use DIC or GAMG "
                << "for " << fieldName_ << exit(FatalError);
        }
        diagonal_[rowi] = sqrt(pivot);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCoupling::envelopeCholesky::envelopeCholesky
(
    const lduMatrix::solver& sol,
    const scalar maxEntriesPerCell
)
:
    fieldName_(sol.fieldName()),
    sign_(1)
{
    const lduMatrix& matrix = sol.matrix();
    if (!matrix.symmetric() && !matrix.diagonal())
    {
        FatalErrorInFunction
            << "system/fvSolution: solvers." << fieldName_ << ": the matrix "
            << "of " << fieldName_ << " is not symmetric; the "
            << "envelopeCholesky preconditioner (for PCG) needs a symmetric "
            << "one. Use PBiCGStab with DILU for " << fieldName_
            << exit(FatalError);
    }

    collectEntries(sol, diag_, entryCell0_, entryCell1_, entryValue_);
    if (diag_.size() && diag_[0] < 0)
    {
        sign_ = -1;
    }

    layOut(maxEntriesPerCell);
    factorise();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::demCoupling::envelopeCholesky::sameMatrix
(
    const lduMatrix::solver& sol
) const
{
    if (sol.matrix().diag().size() != diag_.size())
    {
        return false;
    }

    scalarField diag;
    labelList cell0;
    labelList cell1;
    scalarField value;
    collectEntries(sol, diag, cell0, cell1, value);

    return
        diag == diag_
     && cell0 == entryCell0_
     && cell1 == entryCell1_
     && value == entryValue_;
}


void Foam::demCoupling::envelopeCholesky::solve
(
    solveScalarField& x,
    const solveScalarField& b
) const
{
    const label nCells = diagonal_.size();
    solveScalarField y(nCells);
    forAll(y, rowi)
    {
        y[rowi] = b[orderedToCell_[rowi]];
    }

    const solveScalar* const __restrict__ entries = lowerEntries_.begin();

    // L y' = y
    for (label rowi = 0; rowi < nCells; ++rowi)
    {
        const label firsti = firstColumn_[rowi];
        const solveScalar* const __restrict__ rowEntries =
            entries + rowStart_[rowi] - firsti;
        solveScalar sum = y[rowi];
        for (label k = firsti; k < rowi; ++k)
        {
            sum -= rowEntries[k]*y[k];
        }
        y[rowi] = sum/diagonal_[rowi];
    }

    // L^T x' = y', column by column from the last
    for (label rowi = nCells - 1; rowi >= 0; --rowi)
    {
        const label firsti = firstColumn_[rowi];
        const solveScalar* const __restrict__ rowEntries =
            entries + rowStart_[rowi] - firsti;
        y[rowi] /= diagonal_[rowi];
        const solveScalar xi = y[rowi];
        for (label k = firsti; k < rowi; ++k)
        {
            y[k] -= rowEntries[k]*xi;
        }
    }

    forAll(y, rowi)
    {
        x[orderedToCell_[rowi]] = sign_*y[rowi];
    }
}
