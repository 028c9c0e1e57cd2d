// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "inputCheck.H"

#include <algorithm>
#include <vector>

namespace
{

// Levenshtein distance: insertions, deletions and substitutions
Foam::label editDistance(const std::string& a, const std::string& b)
{
    std::vector<Foam::label> prev(b.size() + 1), cur(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) prev[j] = j;
    for (size_t i = 1; i <= a.size(); ++i)
    {
        cur[0] = i;
        for (size_t j = 1; j <= b.size(); ++j)
        {
            const Foam::label sub = prev[j - 1] + (a[i - 1] != b[j - 1]);
            cur[j] = std::min(std::min(prev[j] + 1, cur[j - 1] + 1), sub);
        }
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

std::string Foam::demCoupling::inputCheck::sentence(const wordList& words)
{
    std::string s;
    forAll(words, i)
    {
        if (i > 0)
        {
            s += (i + 1 == words.size() ? " and " : ", ");
        }
        s += words[i];
    }
    return s;
}


Foam::word Foam::demCoupling::inputCheck::nearest
(
    const word& key,
    const wordList& candidates
)
{
    word best;
    label bestDistance = labelMax;
    for (const word& k : candidates)
    {
        const label d = editDistance(key, k);
        if (d < bestDistance)
        {
            bestDistance = d;
            best = k;
        }
    }
    // A typo: at most two edits, or a third of the word
    if (bestDistance <= max(label(2), label(key.size()/3)))
    {
        return best;
    }
    return word::null;
}


void Foam::demCoupling::inputCheck::keywords
(
    const dictionary& dict,
    const wordList& allowed
)
{
    for (const word& key : dict.toc())
    {
        if (key == "FoamFile" || allowed.found(key))
        {
            continue;
        }
        FatalIOErrorInFunction(dict)
            << "Unknown keyword '" << key << "' in " << dict.name() << nl;
        const word guess(nearest(key, allowed));
        if (!guess.empty())
        {
            FatalIOError << "    Did you mean '" << guess << "'?" << nl;
        }
        FatalIOError
            << "    Allowed: "
            << (allowed.empty() ? std::string("none") : sentence(allowed)).c_str()
            << exit(FatalIOError);
    }
}


const Foam::dictionary& Foam::demCoupling::inputCheck::subDict
(
    const dictionary& dict,
    const word& name,
    const wordList& allowed
)
{
    const dictionary& sub = dict.subDict(name);
    keywords(sub, allowed);
    return sub;
}


void Foam::demCoupling::inputCheck::unknownModel
(
    const dictionary& dict,
    const word& key,
    const word& name,
    const wordList& validNames
)
{
    FatalIOErrorInFunction(dict)
        << "Unknown " << key << " model " << name << " in " << dict.name()
        << nl;
    const word guess(nearest(name, validNames));
    if (!guess.empty())
    {
        FatalIOError << "    Did you mean '" << guess << "'?" << nl;
    }
    FatalIOError
        << "    Valid " << key << " models: " << sentence(validNames).c_str()
        << exit(FatalIOError);
}


void Foam::demCoupling::inputCheck::wrongWord
(
    const dictionary& dict,
    const word& key,
    const word& w,
    const wordList& words,
    const std::string& allowed
)
{
    FatalIOErrorInFunction(dict)
        << key << " '" << w << "' in " << dict.name() << ": allowed are "
        << allowed.c_str();
    const word guess(nearest(w, words));
    if (!guess.empty())
    {
        FatalIOError << nl << "    Did you mean '" << guess << "'?";
    }
    FatalIOError << exit(FatalIOError);
}


// ************************************************************************* //
