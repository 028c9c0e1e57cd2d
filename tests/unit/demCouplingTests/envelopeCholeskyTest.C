// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
// The envelopeCholesky preconditioner (linearSolvers/): on one processor
// it is the matrix's exact inverse, so PCG with it meets a tolerance of
// 1e-13 in one iteration (two allowed for round-off) where DIC takes tens,
// and gives DIC's solution; its factor is kept while the matrix is the
// same and made again when a coefficient changes (a stale factor would no
// longer be the inverse: more iterations); a matrix that is not definite
// stops with the field named, and so does a factor larger than
// maxEnvelopePerCell allows.

#include <gtest/gtest.h>
#include "testMain.H"
#include "fvCFD.H"
#include "envelopeCholeskyPreconditioner.H"

using namespace Foam;
using testing_demCoupling::errorMessage;

namespace
{

//- A field on the test mesh, fixed (0) on its walls
autoPtr<volScalarField> newPsi
(
    const fvMesh& mesh,
    const word& name = "psiEnvelope"
)
{
    return autoPtr<volScalarField>::New
    (
        IOobject
        (
            name, mesh.time().timeName(), mesh,
            IOobject::NO_READ, IOobject::NO_WRITE, false
        ),
        mesh,
        dimensionedScalar(dimless, Zero),
        wordList(mesh.boundary().size(), "fixedValue")
    );
}

//- A source with structure in every direction
tmp<volScalarField::Internal> source(const fvMesh& mesh)
{
    const volScalarField::Internal& x = mesh.C()().component(vector::X)();
    const volScalarField::Internal& y = mesh.C()().component(vector::Y)();
    const volScalarField::Internal& z = mesh.C()().component(vector::Z)();
    tmp<volScalarField::Internal> tb
    (
        new volScalarField::Internal
        (
            IOobject("b", mesh.time().timeName(), mesh),
            mesh,
            dimensionedScalar(dimless/dimArea, Zero)
        )
    );
    volScalarField::Internal& b = tb.ref();
    forAll(b, celli)
    {
        b[celli] = 1e4*(Foam::sin(700*x[celli]) + Foam::cos(900*y[celli]) + 3e2*z[celli]);
    }
    return tb;
}

dictionary solverDict(const word& preconditioner)
{
    dictionary dict;
    dict.add("solver", "PCG");
    dict.add("preconditioner", preconditioner);
    dict.add("tolerance", 1e-13);
    dict.add("relTol", 0.0);
    return dict;
}

//- Solve laplacian(psi) + shift psi = b with PCG and the preconditioner
//  (shift <= 0 keeps the matrix negative definite); the iterations, psi
//  left with the solution
label solveWith
(
    volScalarField& psi,
    const scalar shift,
    const word& preconditioner
)
{
    psi = dimensionedScalar(psi.dimensions(), Zero);
    fvScalarMatrix eqn
    (
        fvm::laplacian(psi)
      + fvm::Sp(dimensionedScalar("shift", dimless/dimArea, shift), psi)
     == source(psi.mesh())
    );
    return eqn.solve(solverDict(preconditioner)).nIterations();
}

scalar maxDifference(const scalarField& a, const scalarField& b)
{
    return max(mag(a - b))/max(max(mag(b)), VSMALL);
}

} // End anonymous namespace


TEST(envelopeCholesky, OneIterationAndDICsSolution)
{
    const fvMesh& mesh = testing_demCoupling::mesh();
    autoPtr<volScalarField> psi(newPsi(mesh));

    const label nDIC = solveWith(*psi, 0, "DIC");
    const scalarField byDIC(psi->primitiveField());

    const label nEnvelope = solveWith(*psi, 0, "envelopeCholesky");
    EXPECT_LE(nEnvelope, 2) << "DIC: " << nDIC;
    EXPECT_GE(nDIC, 10);   // the problem is not trivial for PCG
    EXPECT_LT(maxDifference(psi->primitiveField(), byDIC), 1e-9);
}


TEST(envelopeCholesky, KeptWhileTheMatrixIsTheSameRemadeWhenItChanges)
{
    const fvMesh& mesh = testing_demCoupling::mesh();
    autoPtr<volScalarField> psi(newPsi(mesh));

    solveWith(*psi, 0, "envelopeCholesky");
    const label made = demCoupling::envelopeCholeskyPreconditioner::nFactorisations();

    // the same matrix again: the kept factor
    EXPECT_LE(solveWith(*psi, 0, "envelopeCholesky"), 2);
    EXPECT_EQ(demCoupling::envelopeCholeskyPreconditioner::nFactorisations(), made);

    // other coefficients (not a multiple of the first: PCG would absorb a
    // factor), the same field name: a new factor, still exact
    solveWith(*psi, -1e6, "DIC");
    const scalarField byDIC(psi->primitiveField());
    EXPECT_LE(solveWith(*psi, -1e6, "envelopeCholesky"), 2);
    EXPECT_EQ(demCoupling::envelopeCholeskyPreconditioner::nFactorisations(), made + 1);
    EXPECT_LT(maxDifference(psi->primitiveField(), byDIC), 1e-9);
}


TEST(envelopeCholesky, IndefiniteMatrixNamesTheField)
{
    const fvMesh& mesh = testing_demCoupling::mesh();
    autoPtr<volScalarField> psi(newPsi(mesh));

    fvScalarMatrix eqn(fvm::laplacian(*psi) == source(mesh));
    // one diagonal entry of the wrong sign: no longer definite
    eqn.diag()[mesh.nCells()/2] *= -3;

    const std::string msg = errorMessage
    (
        [&]{ eqn.solve(solverDict("envelopeCholesky")); }
    );
    EXPECT_NE(msg.find("the matrix of psiEnvelope is not definite"), std::string::npos) << msg;
    EXPECT_NE(msg.find("use DIC or GAMG"), std::string::npos) << msg;
}


TEST(envelopeCholesky, EnvelopeAboveTheLimitNamesTheKeyword)
{
    const fvMesh& mesh = testing_demCoupling::mesh();
    // a field of its own: a factor of this name is not yet kept
    autoPtr<volScalarField> psi(newPsi(mesh, "psiEnvelopeLimit"));

    // the 5 x 5 x 5 mesh's envelope holds about 15 entries per cell
    dictionary preconditioner;
    preconditioner.add("preconditioner", "envelopeCholesky");
    preconditioner.add("maxEnvelopePerCell", 2);
    dictionary dict(solverDict("envelopeCholesky"));
    dict.set("preconditioner", preconditioner);

    fvScalarMatrix eqn(fvm::laplacian(*psi) == source(mesh));
    const std::string msg = errorMessage([&]{ eqn.solve(dict); });
    EXPECT_NE(msg.find("more than maxEnvelopePerCell 2"), std::string::npos) << msg;
    EXPECT_NE(msg.find("psiEnvelopeLimit"), std::string::npos) << msg;

    // a limit that is not > 0: the keyword, the value and the rule
    preconditioner.set("maxEnvelopePerCell", -1);
    dict.set("preconditioner", preconditioner);
    const std::string negative = errorMessage([&]{ eqn.solve(dict); });
    EXPECT_NE(negative.find("maxEnvelopePerCell -1"), std::string::npos) << negative;
    EXPECT_NE(negative.find("must be > 0"), std::string::npos) << negative;

    // the default limit: it runs
    EXPECT_LE(solveWith(*psi, 0, "envelopeCholesky"), 2);
}
