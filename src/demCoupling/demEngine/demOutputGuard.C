// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
/*---------------------------------------------------------------------------*\
    interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
    Licence: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "demOutputGuard.H"
#include "error.H"
#include "Pstream.H"

#include <unistd.h>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const long Foam::demCoupling::demOutputGuard::maxRepeats = 10000;

const long long Foam::demCoupling::demOutputGuard::maxBytesPerCommand =
    64LL*1024*1024;


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

ssize_t Foam::demCoupling::demOutputGuard::cookieWrite
(
    void* self,
    const char* buf,
    size_t n
)
{
    return static_cast<demOutputGuard*>(self)->take(buf, n);
}


int Foam::demCoupling::demOutputGuard::cookieClose(void* self)
{
    demOutputGuard& g = *static_cast<demOutputGuard*>(self);
    g.stream_ = nullptr;
    int rc = 0;
    if (g.target_)
    {
        rc = g.ownsTarget_ ? std::fclose(g.target_) : std::fflush(g.target_);
        g.target_ = nullptr;
    }
    return rc;
}


ssize_t Foam::demCoupling::demOutputGuard::take(const char* buf, size_t n)
{
    if (tripped_ || !target_)
    {
        return n;   // swallowed: the run is being stopped
    }

    commandBytes_ += n;
    for (size_t i = 0; i < n; ++i)
    {
        if (buf[i] != '\n')
        {
            if (line_.size() < 4096)
            {
                line_ += buf[i];
            }
            continue;
        }
        if (line_ == lastLine_)
        {
            ++repeats_;
        }
        else
        {
            lastLine_.swap(line_);
            repeats_ = 1;
        }
        line_.clear();
        if (onError_ && lastLine_.compare(0, 5, "ERROR") == 0)
        {
            // LIGGGHTS reports an error and is about to exit or abort:
            // keep its line, then stop the run with its message
            std::fwrite(buf, 1, i + 1, target_);
            std::fflush(target_);
            tripped_ = true;
            onError_(lastLine_);
            return n;
        }
        if (repeats_ > maxRepeats)
        {
            std::fwrite(buf, 1, i + 1, target_);
            stop
            (
                "LIGGGHTS wrote the same line more than "
              + std::to_string(maxRepeats) + " times in a row to the "
              + what_ + ":\n    " + lastLine_
            );
            return n;
        }
    }
    if (commandBytes_ > maxBytesPerCommand)
    {
        std::fwrite(buf, 1, n, target_);
        stop
        (
            "LIGGGHTS wrote more than "
          + std::to_string(maxBytesPerCommand/(1024*1024))
          + " MB to the " + what_ + " in one command"
        );
        return n;
    }

    const size_t written = std::fwrite(buf, 1, n, target_);
    return written == n ? ssize_t(n) : -1;
}


void Foam::demCoupling::demOutputGuard::stop(const std::string& why)
{
    tripped_ = true;
    std::fflush(target_);
    FatalErrorInFunction
        << why.c_str() << nl
        << "    while running: " << command_.c_str() << nl
        << "    A DEM that repeats itself without end (for example"
        << " LIGGGHTS reading a damaged restart file) is stopped here, so"
        << " that it cannot fill the disk. Everything written before is"
        << " kept." << exit(FatalError);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCoupling::demOutputGuard::demOutputGuard
(
    const std::string& what,
    FILE* target,
    bool ownsTarget,
    const errorHook& onError
)
:
    what_(what),
    target_(target),
    ownsTarget_(ownsTarget),
    stream_(nullptr),
    repeats_(0),
    commandBytes_(0),
    tripped_(false),
    command_(),
    onError_(onError)
{
    cookie_io_functions_t io;
    io.read = nullptr;
    io.write = &demOutputGuard::cookieWrite;
    io.seek = nullptr;
    io.close = &demOutputGuard::cookieClose;
    stream_ = fopencookie(this, "w", io);
    if (!stream_)
    {
        FatalErrorInFunction
            << "Cannot open a stream for the DEM's " << what.c_str()
            << exit(FatalError);
    }
    // Line-buffered, as a terminal: a message is out before the next one
    std::setvbuf(stream_, nullptr, _IOLBF, 0);
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * //

Foam::demCoupling::demOutputGuard::~demOutputGuard()
{
    if (stream_)
    {
        std::fclose(stream_);   // cookieClose closes or flushes the target
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::demCoupling::demOutputGuard::startCommand(const std::string& command)
{
    command_ = command;
    commandBytes_ = 0;
}


void Foam::demCoupling::demOutputGuard::append(const std::string& line)
{
    if (target_)
    {
        std::fputs((line + "\n").c_str(), target_);
        std::fflush(target_);
    }
}


// ************************************************************************* //
