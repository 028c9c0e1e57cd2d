// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "turbulenceDragDamping.H"
#include "fvMatrices.H"
#include "fvmSup.H"

namespace Foam
{
namespace demCoupling
{
    defineTypeNameAndDebug(turbulenceDragDamping, 0);
}
}

const Foam::scalar Foam::demCoupling::turbulenceDragDamping::C3eps = 1.2;


namespace
{
    // The option's dictionary: active, nothing else
    Foam::dictionary optionDict()
    {
        Foam::dictionary d;
        d.add("active", true);
        return d;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCoupling::turbulenceDragDamping::turbulenceDragDamping
(
    const fvMesh& mesh,
    const volScalarField& Ksl,
    const volScalarField& rho,
    const wordList& fieldNames
)
:
    fv::option("particleDragDamping", typeName, optionDict(), mesh),
    Ksl_(Ksl),
    rho_(rho)
{
    fieldNames_ = fieldNames;
    applied_.setSize(fieldNames_.size(), false);
    Info<< "Turbulence damped by the particles' drag (Chauchat et al. 2017):"
        << " " << flatOutput(fieldNames_) << endl;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

Foam::tmp<Foam::volScalarField::Internal>
Foam::demCoupling::turbulenceDragDamping::coefficient
(
    const dimensionSet& rhoDims,
    const label fieldi
) const
{
    const word& field = fieldNames_[fieldi];
    scalar factor = 2;                          // k
    if (field.startsWith("epsilon"))
    {
        factor = 2*C3eps;
    }
    else if (field.startsWith("omega"))
    {
        factor = 2*(C3eps - 1);
    }
    if (rhoDims == dimless)
    {
        // a kinematic equation: per unit mass
        return tmp<volScalarField::Internal>::New
        (
            "dragDamping",
            factor*Ksl_()/rho_()
        );
    }
    return tmp<volScalarField::Internal>::New("dragDamping", factor*Ksl_());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::demCoupling::turbulenceDragDamping::addSup
(
    fvMatrix<scalar>& eqn,
    const label fieldi
)
{
    eqn -= fvm::Sp(coefficient(dimless, fieldi), eqn.psi());
}


void Foam::demCoupling::turbulenceDragDamping::addSup
(
    const volScalarField& rho,
    fvMatrix<scalar>& eqn,
    const label fieldi
)
{
    eqn -= fvm::Sp(coefficient(rho.dimensions(), fieldi), eqn.psi());
}


void Foam::demCoupling::turbulenceDragDamping::addSup
(
    const volScalarField& alpha,
    const volScalarField& rho,
    fvMatrix<scalar>& eqn,
    const label fieldi
)
{
    eqn -= fvm::Sp(coefficient(rho.dimensions(), fieldi), eqn.psi());
}


// ************************************************************************* //
