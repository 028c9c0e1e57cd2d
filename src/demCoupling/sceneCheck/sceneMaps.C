// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "sceneMaps.H"
#include "error.H"
#include "OSspecific.H"

#include <algorithm>
#include <fstream>
#include <sstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

// The data rows of a table (comment and empty lines skipped), split into
// words; FatalError naming the file when it cannot be read
Foam::List<Foam::List<std::string>> readRows(const Foam::fileName& file)
{
    std::ifstream is(file.c_str());
    if (!is.good())
    {
        FatalErrorInFunction
            << "Cannot read the measured map " << file << Foam::nl
            << "    The measured maps are the project's own tables in"
            << " etc/sceneMaps/ (INTERDEMFOAM_DIR; checkDemScene -maps DIR)"
            << Foam::exit(Foam::FatalError);
    }
    Foam::DynamicList<Foam::List<std::string>> rows;
    std::string line;
    while (std::getline(is, line))
    {
        if (line.empty() || line[0] == '#')
        {
            continue;
        }
        std::istringstream ls(line);
        Foam::DynamicList<std::string> words;
        std::string w;
        while (ls >> w)
        {
            words.append(w);
        }
        if (!words.empty())
        {
            rows.append(words);
        }
    }
    return rows;
}


// FatalError unless row r has at least n columns
void requireColumns
(
    const Foam::List<std::string>& r,
    const Foam::label n,
    const Foam::fileName& file
)
{
    if (r.size() < n)
    {
        FatalErrorInFunction
            << "A row of " << file << " has " << r.size() << " columns, "
            << n << " or more expected" << Foam::exit(Foam::FatalError);
    }
}


Foam::scalar number
(
    const std::string& s,
    const Foam::fileName& file
)
{
    try
    {
        std::size_t used = 0;
        const double v = std::stod(s, &used);
        if (used == s.size())
        {
            return v;
        }
    }
    catch (...)
    {}
    if (s == "nan")
    {
        return Foam::GREAT;
    }
    FatalErrorInFunction
        << "Not a number '" << s.c_str() << "' in " << file
        << Foam::exit(Foam::FatalError);
    return 0;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::demCoupling::sceneMaps::sceneMaps(const fileName& dir)
:
    dir_(dir)
{
    // mesh study: model dx/d v_terminal error[%] v_range wall floorHits ran
    const fileName study(dir/"meshStudy.dat");
    for (const List<std::string>& r : readRows(study))
    {
        requireColumns(r, 6, study);
        const word model(r[0]);
        label m = modelIndex(model);
        if (m < 0)
        {
            models_.append(model);
            points_.resize(models_.size());
            m = models_.size() - 1;
        }
        point p;
        p.dxOverD = number(r[1], study);
        p.errorPercent = number(r[3], study);
        p.wallSeconds = number(r[5], study);
        points_[m].append(p);
    }
    // stability map: model dx/d bounded ended nonFinite minEps ...
    const fileName stability(dir/"stabilityMap.dat");
    for (const List<std::string>& r : readRows(stability))
    {
        requireColumns(r, 3, stability);
        const label m = modelIndex(word(r[0]));
        if (m < 0)
        {
            continue;
        }
        const scalar x = number(r[1], stability);
        for (point& p : points_[m])
        {
            if (mag(p.dxOverD - x) < 1e-9)
            {
                p.bounded = (r[2] == "yes") ? 1 : 0;
            }
        }
    }
    // drag stability: scene scheme dt dt/tau error blown
    const fileName drag(dir/"dragStability.dat");
    for (const List<std::string>& r : readRows(drag))
    {
        requireColumns(r, 6, drag);
        dragRun d;
        d.scene = r[0];
        d.scheme = r[1];
        d.dtOverTau = number(r[3], drag);
        d.blown = number(r[5], drag) > 0.5;
        dragRuns_.append(d);
    }
    // bedload onsets (optional): model below onset source
    const fileName onsets(dir/"bedloadOnset.dat");
    if (isFile(onsets))
    {
        for (const List<std::string>& r : readRows(onsets))
        {
            requireColumns(r, 3, onsets);
            onsetModels_.append(word(r[0]));
            onsetBelow_.append(number(r[1], onsets));
            onsetAt_.append(number(r[2], onsets));
        }
    }
    if (models_.empty())
    {
        FatalErrorInFunction
            << "No void-fraction model in " << study << exit(FatalError);
    }
    // Points by cell size
    for (DynamicList<point>& pts : points_)
    {
        std::sort
        (
            pts.begin(), pts.end(),
            [](const point& a, const point& b) { return a.dxOverD < b.dxOverD; }
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::fileName Foam::demCoupling::sceneMaps::defaultDir()
{
    return fileName(getEnv("INTERDEMFOAM_DIR"))/"etc"/"sceneMaps";
}


bool Foam::demCoupling::sceneMaps::bedloadOnset
(
    const word& model,
    scalar& below,
    scalar& onset
) const
{
    forAll(onsetModels_, i)
    {
        if (onsetModels_[i] == model)
        {
            below = onsetBelow_[i];
            onset = onsetAt_[i];
            return true;
        }
    }
    return false;
}


bool Foam::demCoupling::sceneMaps::available(const fileName& dir)
{
    return
        isFile(dir/"meshStudy.dat") && isFile(dir/"stabilityMap.dat")
     && isFile(dir/"dragStability.dat");
}


Foam::label Foam::demCoupling::sceneMaps::modelIndex(const word& model) const
{
    forAll(models_, i)
    {
        if (models_[i] == model)
        {
            return i;
        }
    }
    return -1;
}


const Foam::demCoupling::sceneMaps::point&
Foam::demCoupling::sceneMaps::below
(
    const label m,
    const scalar dxOverD
) const
{
    const DynamicList<point>& pts = points_[m];
    label k = 0;
    forAll(pts, i)
    {
        if (pts[i].dxOverD <= dxOverD + 1e-9)
        {
            k = i;
        }
    }
    return pts[k];
}


Foam::scalar Foam::demCoupling::sceneMaps::expectedError
(
    const word& model,
    const scalar dxOverD,
    bool& inRange
) const
{
    const label m = modelIndex(model);
    if (m < 0)
    {
        inRange = false;
        return -1;
    }
    const DynamicList<point>& pts = points_[m];
    inRange =
        dxOverD >= pts.first().dxOverD - 1e-9
     && dxOverD <= pts.last().dxOverD + 1e-9;
    if (dxOverD <= pts.first().dxOverD)
    {
        return mag(pts.first().errorPercent);
    }
    if (dxOverD >= pts.last().dxOverD)
    {
        return mag(pts.last().errorPercent);
    }
    for (label i = 1; i < pts.size(); ++i)
    {
        if (dxOverD <= pts[i].dxOverD)
        {
            const scalar w =
                (dxOverD - pts[i-1].dxOverD)
               /(pts[i].dxOverD - pts[i-1].dxOverD);
            return (1 - w)*mag(pts[i-1].errorPercent)
                + w*mag(pts[i].errorPercent);
        }
    }
    return mag(pts.last().errorPercent);
}


int Foam::demCoupling::sceneMaps::bounded
(
    const word& model,
    const scalar dxOverD,
    scalar& atDxOverD
) const
{
    const label m = modelIndex(model);
    if (m < 0)
    {
        atDxOverD = -1;
        return -1;
    }
    // The stability runs only (the mesh study has sizes they lack): the
    // largest measured size at or below dxOverD; below the smallest one
    // a failure there holds (smaller is harder), a pass says nothing
    const point* at = nullptr;
    const point* smallest = nullptr;
    for (const point& p : points_[m])
    {
        if (p.bounded < 0)
        {
            continue;
        }
        if (!smallest)
        {
            smallest = &p;
        }
        if (p.dxOverD <= dxOverD + 1e-9)
        {
            at = &p;
        }
    }
    if (!smallest)
    {
        atDxOverD = -1;
        return -1;
    }
    if (!at)
    {
        atDxOverD = smallest->dxOverD;
        return smallest->bounded == 0 ? 0 : -1;
    }
    atDxOverD = at->dxOverD;
    return at->bounded;
}


Foam::scalar Foam::demCoupling::sceneMaps::relativeCost
(
    const word& model,
    const scalar dxOverD
) const
{
    const label m = modelIndex(model);
    const label vs = modelIndex("virtualSphere");
    if (m < 0 || vs < 0)
    {
        return -1;
    }
    const point& p = below(m, dxOverD);
    const point& q = below(vs, dxOverD);
    if (p.wallSeconds >= GREAT || q.wallSeconds <= 0)
    {
        return -1;
    }
    return p.wallSeconds/q.wallSeconds;
}


Foam::scalar Foam::demCoupling::sceneMaps::dragBlowUp
(
    const word& scheme,
    const word& scene,
    scalar& largestStable
) const
{
    scalar worst = GREAT;
    for (const dragRun& d : dragRuns_)
    {
        if
        (
            d.scheme == scheme && d.scene == scene && d.blown
         && d.dtOverTau < worst
        )
        {
            worst = d.dtOverTau;
        }
    }
    largestStable = 0;
    for (const dragRun& d : dragRuns_)
    {
        if
        (
            d.scheme == scheme && d.scene == scene && !d.blown
         && d.dtOverTau < worst && d.dtOverTau > largestStable
        )
        {
            largestStable = d.dtOverTau;
        }
    }
    return worst;
}


Foam::scalar Foam::demCoupling::sceneMaps::smallestDxOverD
(
    const word& model,
    const scalar errorPercent
) const
{
    const label m = modelIndex(model);
    if (m < 0)
    {
        return -1;
    }
    const DynamicList<point>& pts = points_[m];
    scalar result = -1;
    for (label i = pts.size() - 1; i >= 0; --i)
    {
        if (mag(pts[i].errorPercent) <= errorPercent && pts[i].bounded != 0)
        {
            result = pts[i].dxOverD;
        }
        else
        {
            break;
        }
    }
    return result;
}


// ************************************************************************* //
