// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "velocityFluctuation.H"
#include "mathematicalConstants.H"
#include "error.H"
#include "inputCheck.H"

#include <cmath>
#include <cstdint>

namespace
{

// A 64-bit mixing function (the finaliser of the splitmix64 generator):
// consecutive inputs give unrelated outputs
uint64_t mix(uint64_t x)
{
    x += 0x9E3779B97F4A7C15ULL;
    x = (x ^ (x >> 30))*0xBF58476D1CE4E5B9ULL;
    x = (x ^ (x >> 27))*0x94D049BB133111EBULL;
    return x ^ (x >> 31);
}

// A number in (0, 1) from 53 bits of h
double unitOpen(const uint64_t h)
{
    return (double(h >> 11) + 0.5)/9007199254740992.0;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * //

const Foam::Enum
<
    Foam::demCoupling::velocityFluctuation::fluctuationSource
>
Foam::demCoupling::velocityFluctuation::fluctuationSourceNames
({
    { fluctuationSource::fixed, "fixed" },
    { fluctuationSource::turbulence, "turbulence" },
});

const Foam::Enum
<
    Foam::demCoupling::velocityFluctuation::eddyLifetimeModel
>
Foam::demCoupling::velocityFluctuation::eddyLifetimeModelNames
({
    { eddyLifetimeModel::crossing, "crossing" },
    { eddyLifetimeModel::turnover, "turnover" },
});

const Foam::Enum
<
    Foam::demCoupling::velocityFluctuation::sizeModel
>
Foam::demCoupling::velocityFluctuation::sizeModelNames
({
    { sizeModel::energy, "k" },
    { sizeModel::shearStress, "shearStress" },
});

const Foam::Enum
<
    Foam::demCoupling::velocityFluctuation::turbulenceSample
>
Foam::demCoupling::velocityFluctuation::turbulenceSampleNames
({
    { turbulenceSample::average, "average" },
    { turbulenceSample::grainTop, "grainTop" },
    { turbulenceSample::cellAbove, "cellAbove" },
});

const Foam::scalar
Foam::demCoupling::velocityFluctuation::streamwisePerFrictionVelocity =
    2.30;

const Foam::scalar
Foam::demCoupling::velocityFluctuation::streamwisePerSqrtK =
    2.30*std::sqrt(2.0/(2.30*2.30 + 1.63*1.63 + 1.27*1.27));

const Foam::scalar Foam::demCoupling::velocityFluctuation::lateralRatio =
    1.63/2.30;

const Foam::scalar Foam::demCoupling::velocityFluctuation::verticalRatio =
    1.27/2.30;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCoupling::velocityFluctuation::velocityFluctuation
(
    const dictionary& dict
)
:
    source_(fluctuationSource::fixed),
    eddyLifetime_(eddyLifetimeModel::crossing),
    size_(sizeModel::energy),
    sampledAt_(turbulenceSample::average),
    intensity_(0),
    eddyTime_(1),
    seed_(0)
{
    const dictionary& all = dict.subDict("velocityFluctuation");
    source_ = inputCheck::selectOrDefault
    (
        all, "source", fluctuationSourceNames, fluctuationSource::fixed,
        "fixed (intensity and eddyTime given; the default) and turbulence"
        " (size and lifetime from the turbulence model's k and epsilon)"
    );
    if (fromTurbulence())
    {
        const dictionary& coeffs = inputCheck::subDict
        (
            dict, "velocityFluctuation",
            {"source", "eddyLifetime", "size", "sampledAt", "seed"}
        );
        eddyLifetime_ = inputCheck::selectOrDefault
        (
            coeffs, "eddyLifetime", eddyLifetimeModelNames,
            eddyLifetimeModel::crossing,
            std::string("crossing (")
          + lifetimeFormula(eddyLifetimeModel::crossing)
          + ", Gosman & Ioannides; the default) and turnover ("
          + lifetimeFormula(eddyLifetimeModel::turnover) + ")"
        );
        size_ = inputCheck::selectOrDefault
        (
            coeffs, "size", sizeModelNames, sizeModel::energy,
            "k (the fluctuation's energy is k; the default) and shearStress"
            " (2.30 nut sqrt(2 S:S) streamwise, Nezu & Nakagawa's near-bed"
            " r.m.s. per friction velocity)"
        );
        sampledAt_ = inputCheck::selectOrDefault
        (
            coeffs, "sampledAt", turbulenceSampleNames,
            turbulenceSample::average,
            "average (the void-fraction average over the particle's cells;"
            " the default), grainTop (at its top, d/2 above its centre) and"
            " cellAbove (in the cell above its host cell: the flow over a"
            " bed's surface)"
        );
        seed_ = inputCheck::getOrDefault<label>
        (
            coeffs, "seed", 0, [](const label s) { return s >= 0; }, ">= 0"
        );
        return;
    }
    const dictionary& coeffs = inputCheck::subDict
    (
        dict, "velocityFluctuation", {"source", "intensity", "eddyTime", "seed"}
    );
    intensity_ = inputCheck::get<scalar>
    (
        coeffs, "intensity", &inputCheck::nonNegative, ">= 0"
    );
    eddyTime_ = inputCheck::get<scalar>
    (
        coeffs, "eddyTime", &inputCheck::positive, "> 0"
    );
    seed_ = inputCheck::getOrDefault<label>
    (
        coeffs, "seed", 0, [](const label s) { return s >= 0; }, ">= 0"
    );
}


Foam::demCoupling::velocityFluctuation::velocityFluctuation
(
    const scalar intensity,
    const scalar eddyTime,
    const label seed
)
:
    source_(fluctuationSource::fixed),
    eddyLifetime_(eddyLifetimeModel::crossing),
    size_(sizeModel::energy),
    sampledAt_(turbulenceSample::average),
    intensity_(intensity),
    eddyTime_(eddyTime),
    seed_(seed)
{}


Foam::demCoupling::velocityFluctuation::velocityFluctuation
(
    const eddyLifetimeModel eddyLifetime,
    const label seed,
    const sizeModel size
)
:
    source_(fluctuationSource::turbulence),
    eddyLifetime_(eddyLifetime),
    size_(size),
    sampledAt_(turbulenceSample::average),
    intensity_(0),
    eddyTime_(1),
    seed_(seed)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::demCoupling::velocityFluctuation::normal
(
    const label tag,
    const int64_t eddy,
    const label k
) const
{
    // Box-Muller from two independent hashes
    const uint64_t base =
        mix(mix(mix(uint64_t(seed_)) ^ uint64_t(tag)) ^ uint64_t(eddy));
    const double u1 = unitOpen(mix(base ^ uint64_t(2*k + 1)));
    const double u2 = unitOpen(mix(base ^ uint64_t(2*k + 2)));
    return std::sqrt(-2.0*std::log(u1))
        *std::cos(constant::mathematical::twoPi*u2);
}


double Foam::demCoupling::velocityFluctuation::phase(const label tag) const
{
    return unitOpen(mix(mix(uint64_t(seed_) ^ 0x5EEDULL) ^ uint64_t(tag)));
}


int64_t Foam::demCoupling::velocityFluctuation::eddy
(
    const label tag,
    const scalar t
) const
{
    // The particle's own shift of the eddy times, in [0, 1) eddyTime
    return int64_t(std::floor(t/eddyTime_ + phase(tag)));
}


Foam::vector Foam::demCoupling::velocityFluctuation::draw
(
    const label tag,
    const int64_t e,
    const vector& es,
    const vector& up,
    const scalar sigma
) const
{
    // Vertical: up made normal to the flow (any normal where the flow is
    // vertical)
    vector ev(up - (up & es)*es);
    if (mag(ev) < 1e-6)
    {
        const vector trial
        (
            mag(es.x()) < 0.9 ? vector(1, 0, 0) : vector(0, 1, 0)
        );
        ev = trial - (trial & es)*es;
    }
    ev /= mag(ev);
    const vector el(ev ^ es);

    return sigma
       *(
            normal(tag, e, 0)*es
          + lateralRatio*normal(tag, e, 1)*el
          + verticalRatio*normal(tag, e, 2)*ev
        );
}


Foam::vector Foam::demCoupling::velocityFluctuation::operator()
(
    const label tag,
    const scalar t,
    const vector& U,
    const vector& up
) const
{
    const scalar magU = mag(U);
    if (intensity_ <= 0 || magU < VSMALL)
    {
        return Zero;
    }
    return draw(tag, eddy(tag, t), U/magU, up, intensity_*magU);
}


const char* Foam::demCoupling::velocityFluctuation::lifetimeFormula
(
    const eddyLifetimeModel model
)
{
    return model == eddyLifetimeModel::turnover
        ? "k/epsilon"
        : "l_e/max(sqrt(2k/3), |u - v|)";
}


Foam::scalar Foam::demCoupling::velocityFluctuation::lifetime
(
    const scalar k,
    const scalar epsilon,
    const scalar slip
) const
{
    if (eddyLifetime_ == eddyLifetimeModel::turnover)
    {
        // The energy-carrying eddies' turnover time
        return k/epsilon;
    }
    const scalar Cmu = 0.09;
    const scalar le = std::pow(Cmu, 0.75)*std::pow(k, 1.5)/epsilon;
    // Gosman & Ioannides (1983): the eddy's length and the quicker of the
    // particle's ways out of it, the eddy's own decay or crossing it
    return le/max(std::sqrt(2.0*k/3.0), slip);
}


Foam::vector Foam::demCoupling::velocityFluctuation::turbulent
(
    const label tag,
    const scalar t,
    const vector& U,
    const vector& up,
    const scalar k,
    const scalar epsilon,
    const scalar slip,
    const scalar shear
) const
{
    if (!(k > SMALL) || !(epsilon > SMALL))
    {
        return Zero;
    }
    const scalar sigma =
        size_ == sizeModel::shearStress
      ? streamwisePerFrictionVelocity*std::sqrt(max(shear, scalar(0)))
      : streamwisePerSqrtK*std::sqrt(k);
    // Streamwise along U; where the fluid rests, any horizontal direction
    const scalar magU = mag(U);
    vector es(U/max(magU, VSMALL));
    if (magU < VSMALL)
    {
        const vector trial
        (
            mag(up.x()) < 0.9 ? vector(1, 0, 0) : vector(0, 1, 0)
        );
        es = trial - (trial & up)*up;
        es /= mag(es);
    }
    const scalar T = lifetime(k, epsilon, slip);
    const int64_t e = int64_t(std::floor(t/T + phase(tag)));
    return draw(tag, e, es, up, sigma);
}


// ************************************************************************* //
