// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "forceModel.H"
#include "inputCheck.H"
#include "couplingKeywords.H"

namespace Foam
{
namespace demCoupling
{
    defineTypeNameAndDebug(forceModel, 0);
    defineRunTimeSelectionTable(forceModel, dictionary);
}
}

namespace
{
    // The keywords of couplingProperties this family reads
    const Foam::demCoupling::couplingKeywords::declare keywords
    (
        {"forces"},
        &Foam::demCoupling::forceModel::modelNames
    );
}


Foam::demCoupling::forceModel::forceModel(const dictionary& coeffs)
:
    coeffs_(coeffs)
{}


Foam::autoPtr<Foam::demCoupling::forceModel>
Foam::demCoupling::forceModel::New
(
    const word& name,
    const dictionary& dict
)
{
    auto cstrIter = dictionaryConstructorTablePtr_->cfind(name);

    if (!cstrIter.found())
    {
        inputCheck::unknownModel(dict, "forces", name, modelNames());
    }

    Info<< "Selecting force model " << name << endl;

    return autoPtr<forceModel>
    (
        cstrIter()(dict.subOrEmptyDict(name + "Coeffs"))
    );
}


Foam::PtrList<Foam::demCoupling::forceModel>
Foam::demCoupling::forceModel::NewList(const dictionary& dict)
{
    const wordList names(dict.get<wordList>("forces"));

    if (names.empty())
    {
        Info<< "Warning: forces () in " << dict.name() << " lists no force"
            << " model: the particles feel no fluid and the fluid no"
            << " particle but through the void fraction. List the models"
            << " the scene needs, e.g. forces ( DiFeliceDrag"
            << " pressureGradient );" << endl;
    }

    PtrList<forceModel> models(names.size());
    forAll(names, i)
    {
        for (label j = 0; j < i; ++j)
        {
            if (names[j] == names[i])
            {
                FatalIOErrorInFunction(dict)
                    << "Force model " << names[i] << " listed twice in "
                    << "'forces'" << exit(FatalIOError);
            }
        }
        models.set(i, New(names[i], dict));
    }
    return models;
}


Foam::wordList Foam::demCoupling::forceModel::modelNames()
{
    return dictionaryConstructorTablePtr_->sortedToc();
}
