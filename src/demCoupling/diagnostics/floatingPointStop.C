// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "floatingPointStop.H"
#include "error.H"
#include "Pstream.H"

#include <csignal>
#include <cstdio>
#include <unistd.h>
#include <mpi.h>

namespace
{

// What the handler reports (set while the solver runs)
const Foam::Time* runTimePtr = nullptr;
double lastWrite = 0;
bool parallel = false;

void write(const char* s)
{
    std::size_t n = 0;
    while (s[n]) ++n;
    while (n > 0)
    {
        const ssize_t w = ::write(STDERR_FILENO, s, n);
        if (w <= 0) break;
        s += w;
        n -= std::size_t(w);
    }
}

extern "C" void blowUp(int)
{
    // Trapping off: the report itself may not trap again
    std::signal(SIGFPE, SIG_DFL);

    char msg[1024];
    const double t = runTimePtr ? runTimePtr->value() : -1;
    std::snprintf
    (
        msg, sizeof(msg),
        "\n--> FOAM FATAL ERROR: the solution blew up: a floating-point"
        " exception (overflow, division by zero or an invalid operation)"
        " in the step to t = %.10g s.\n"
        "    The last complete write time, %.10g s, is kept (startFrom"
        " latestTime continues from it; nothing written is lost).\n"
        "    Look in the log above at the Courant numbers, the DEM step"
        " against the Rayleigh time, the void-fraction floor hits and the"
        " particle sizes against the cells.\n\n", t, lastWrite
    );
    write(msg);
    Foam::error::printStack(Foam::Perr);
    Foam::Perr.flush();
    if (parallel)
    {
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
    ::_exit(1);
}

} // End anonymous namespace


void Foam::demCoupling::floatingPointStop::install(const Time& runTime)
{
    runTimePtr = &runTime;
    lastWrite = runTime.value();     // the start time's files
    parallel = Pstream::parRun();

    struct sigaction action;
    action.sa_handler = &blowUp;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_NODEFER;
    sigaction(SIGFPE, &action, nullptr);
}


void Foam::demCoupling::floatingPointStop::written(const Time& runTime)
{
    lastWrite = runTime.value();
}


// ************************************************************************* //
