// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "couplingKeywords.H"
#include "DynamicList.H"

#include <vector>

namespace
{

// The declarations, filled while the library loads (function-local
// statics: safe whatever the order in which the rooms' statics are built)
Foam::DynamicList<Foam::word>& declaredKeywords()
{
    static Foam::DynamicList<Foam::word> keywords;
    return keywords;
}

std::vector<Foam::demCoupling::couplingKeywords::modelNamesFunction>&
declaredFamilies()
{
    static std::vector
    <
        Foam::demCoupling::couplingKeywords::modelNamesFunction
    > families;
    return families;
}

} // End anonymous namespace


Foam::demCoupling::couplingKeywords::declare::declare
(
    std::initializer_list<const char*> keywords,
    modelNamesFunction models
)
{
    for (const char* k : keywords)
    {
        declaredKeywords().append(word(k));
    }
    if (models)
    {
        declaredFamilies().push_back(models);
    }
}


Foam::wordList Foam::demCoupling::couplingKeywords::allowed()
{
    DynamicList<word> all(declaredKeywords());
    for (const modelNamesFunction models : declaredFamilies())
    {
        for (const word& m : models())
        {
            all.append(m + "Coeffs");
        }
    }
    wordList sorted(std::move(all));
    Foam::sort(sorted);
    return sorted;
}


// ************************************************************************* //
