// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
/*---------------------------------------------------------------------------*\
    interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
    Licence: GPL-3.0-or-later (see LICENSE)
\*---------------------------------------------------------------------------*/

#include "demRestartFile.H"
#include "OSspecific.H"
#include "Pstream.H"
#include "SHA1.H"
#include "IOobject.H"
#include "IOdictionary.H"
#include "OFstream.H"

#include <fstream>
#include <sstream>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>
#include <sys/statvfs.h>
#include <sys/resource.h>

namespace
{

// SHA-1 of a whole file, hex
std::string fileSha1(const Foam::fileName& file)
{
    std::ifstream is(file.c_str(), std::ios::binary);
    Foam::SHA1 sha;
    std::vector<char> buf(1 << 20);
    while (is)
    {
        is.read(buf.data(), buf.size());
        sha.append(buf.data(), size_t(is.gcount()));
    }
    return sha.str();
}


// Free space and the file-size limit where a file is written, for the
// message of a failed write
std::string spaceNote(const Foam::fileName& file)
{
    std::ostringstream os;
    struct statvfs fs;
    if (::statvfs(file.path().c_str(), &fs) == 0)
    {
        os  << "free space on its file system: "
            << (double(fs.f_bavail)*fs.f_frsize)/(1024.0*1024.0) << " MB";
    }
    struct rlimit lim;
    if (::getrlimit(RLIMIT_FSIZE, &lim) == 0 && lim.rlim_cur != RLIM_INFINITY)
    {
        os  << "; file-size limit (ulimit -f): " << lim.rlim_cur << " bytes";
    }
    return os.str();
}


// Write text to file durably: temporary name, write, fsync, rename.
// Empty on success, else what failed.
std::string writeDurably(const Foam::fileName& file, const std::string& text)
{
    const std::string tmp(file + ".writing");
    const int fd = ::open(tmp.c_str(), O_WRONLY|O_CREAT|O_TRUNC, 0644);
    if (fd < 0)
    {
        return "cannot create " + tmp + ": " + std::strerror(errno);
    }
    size_t done = 0;
    while (done < text.size())
    {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n <= 0)
        {
            const std::string why(std::strerror(errno));
            ::close(fd);
            ::unlink(tmp.c_str());
            return "cannot write " + tmp + ": " + why;
        }
        done += size_t(n);
    }
    if (::fsync(fd) != 0 || ::close(fd) != 0)
    {
        const std::string why(std::strerror(errno));
        ::unlink(tmp.c_str());
        return "cannot flush " + tmp + ": " + why;
    }
    if (::rename(tmp.c_str(), file.c_str()) != 0)
    {
        return "cannot rename " + tmp + ": " + std::strerror(errno);
    }
    return std::string();
}


// The atom section LIGGGHTS writes last: per rank, in rank order, an int n
// and n doubles. Walked back from the end of the file.
std::string checkAtomBlocks
(
    const Foam::fileName& file,
    const Foam::labelList& blockDoubles
)
{
    std::ifstream is(file.c_str(), std::ios::binary);
    if (!is)
    {
        return "cannot open it";
    }
    is.seekg(0, std::ios::end);
    long long pos = is.tellg();
    const long long size = pos;
    for (Foam::label r = blockDoubles.size() - 1; r >= 0; --r)
    {
        const long long start =
            pos - 8LL*blockDoubles[r] - Foam::label(sizeof(int));
        int n = -1;
        if (start >= 0)
        {
            is.seekg(start);
            is.read(reinterpret_cast<char*>(&n), sizeof(int));
        }
        if (start < 0 || !is || n != blockDoubles[r])
        {
            std::ostringstream os;
            os  << "it is incomplete: " << size << " bytes, but the atom"
                << " block of DEM rank " << r << " (" << blockDoubles[r]
                << " doubles) is not where it must end the file";
            return os.str();
        }
        pos = start;
    }
    return std::string();
}


// OpenFOAM files (those with a FoamFile header) of a folder tree that lack
// OpenFOAM's closing comment line: truncated writes
std::string checkFoamFiles(const Foam::fileName& dir)
{
    using namespace Foam;
    std::string bad;
    for (const fileName& f : readDir(dir, fileName::FILE))
    {
        if (f.hasExt("gz") || f.find("liggghts.restart") == 0)
        {
            continue;
        }
        std::ifstream is((dir/f).c_str(), std::ios::binary);
        std::string head(1024, '\0');
        is.read(&head[0], head.size());
        head.resize(size_t(is.gcount()));
        if (head.find("FoamFile") == std::string::npos)
        {
            continue;
        }
        is.clear();
        is.seekg(0, std::ios::end);
        const long long size = is.tellg();
        std::string tail(size_t(std::min(size, 200LL)), '\0');
        is.seekg(size - static_cast<long long>(tail.size()));
        is.read(&tail[0], tail.size());
        if (tail.find("// *****") == std::string::npos)
        {
            bad += " " + std::string(dir/f) + " (" + std::to_string(size)
                + " bytes, no closing line)";
        }
    }
    for (const fileName& d : readDir(dir, fileName::DIRECTORY))
    {
        bad += checkFoamFiles(dir/d);
    }
    return bad;
}


// Key -> value of a check file ("key value;" lines)
Foam::HashTable<std::string> readCheck(const Foam::fileName& file)
{
    Foam::HashTable<std::string> table;
    std::ifstream is(file.c_str());
    std::string key, value;
    std::string line;
    while (std::getline(is, line))
    {
        std::istringstream ls(line);
        if (ls >> key >> value && value.size() && value.back() == ';')
        {
            value.pop_back();
            table.set(key, value);
        }
    }
    return table;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCoupling::demRestartFile::demRestartFile
(
    const Time& runTime,
    const word& timeName
)
:
    file_(runTime.path()/timeName/"liggghts.restart"),
    timeName_(timeName)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::fileName Foam::demCoupling::demRestartFile::masterFile
(
    const Time& runTime,
    const word& timeName
)
{
    fileName file(demRestartFile(runTime, timeName).file());
    Pstream::scatter(file);
    return file;
}


void Foam::demCoupling::demRestartFile::commit
(
    const Time& runTime,
    const labelList& atomBlockDoubles,
    const label nParticles
) const
{
    // Every rank: its own time folder's OpenFOAM files
    List<string> problems(Pstream::nProcs());
    problems[Pstream::myProcNo()] = checkFoamFiles(runTime.timePath());

    // Master: the DEM file
    string demProblem;
    if (Pstream::master())
    {
        demProblem = checkAtomBlocks(writingFile(), atomBlockDoubles);
        if (!demProblem.empty())
        {
            demProblem =
                "The DEM restart file " + writingFile() + " as written by"
                " LIGGGHTS is bad: " + demProblem + ".\n    ("
              + spaceNote(file_) + ")";
            Foam::rm(writingFile());
        }
        else if (!Foam::mv(writingFile(), file_))
        {
            demProblem =
                "Cannot rename " + writingFile() + " to " + file_;
        }
        else
        {
            // an emptied marker left from an earlier run of this time
            Foam::rm(emptiedFile());
            std::ostringstream text;
            text<< "// interDemFoam: check values of liggghts.restart in"
                << " this folder; a folder without this file is incomplete\n"
                << "time        " << timeName_ << ";\n"
                << "size        " << Foam::fileSize(file_) << ";\n"
                << "sha1        " << fileSha1(file_) << ";\n"
                << "particles   " << nParticles << ";\n";
            const std::string failed(writeDurably(checkFile(), text.str()));
            if (!failed.empty())
            {
                demProblem = failed + "\n    (" + spaceNote(file_) + ")";
            }
        }
    }
    Pstream::gatherList(problems);
    Pstream::scatterList(problems);
    Pstream::scatter(demProblem);

    string fluidProblem;
    forAll(problems, proci)
    {
        fluidProblem += problems[proci];
    }
    if (!demProblem.empty() || !fluidProblem.empty())
    {
        FatalErrorInFunction
            << "The write of t = " << timeName_ << " s failed." << nl;
        if (!demProblem.empty())
        {
            FatalError << "    " << demProblem.c_str() << nl;
        }
        if (!fluidProblem.empty())
        {
            FatalError
                << "    Truncated OpenFOAM files:" << fluidProblem.c_str()
                << nl << "    (" << spaceNote(runTime.timePath()).c_str()
                << ")" << nl;
        }
        FatalError
            << "    The disk is full or a file-size limit was reached. Time "
            << timeName_ << " is incomplete (no " << checkFile().name()
            << "); earlier write times are untouched. Free space, then"
            << " restart: interDemFoam -restartFromLastComplete"
            << exit(FatalError);
    }
}


void Foam::demCoupling::demRestartFile::guardWrite
(
    const Time& runTime,
    const std::function<void()>& write
)
{
    const bool throwing = FatalIOError.throwExceptions();
    try
    {
        write();
    }
    catch (const Foam::IOerror& err)
    {
        FatalIOError.throwExceptions(throwing);
        FatalErrorInFunction
            << "The write of t = " << runTime.timeName() << " s failed: "
            << err.message().c_str() << nl
            << "    in " << err.ioFileName() << nl
            << "    (" << spaceNote(runTime.timePath()).c_str() << ")" << nl
            << "    The disk is full or a file-size limit was reached. Time "
            << runTime.timeName() << " is incomplete (no liggghts.restart.check);"
            << " earlier write times are untouched. Free space, then restart:"
            << " interDemFoam -restartFromLastComplete"
            << exit(FatalError);
    }
    FatalIOError.throwExceptions(throwing);
}


void Foam::demCoupling::demRestartFile::writeFluid(Time& runTime)
{
    guardWrite(runTime, [&runTime]() { runTime.write(); });
}


void Foam::demCoupling::demRestartFile::markEmptied(const Time& runTime) const
{
    if (!Pstream::master())
    {
        return;
    }
    mkDir(file_.path());
    // A DEM state left from an earlier run of this time is not this run's
    Foam::rm(file_);
    Foam::rm(checkFile());
    OFstream os(emptiedFile());
    os  << "// interDemFoam: no DEM restart file at t = " << timeName_
        << " s: every DEM particle had left the domain" << nl
        << "time        " << timeName_ << ';' << nl
        << "particles   0;" << nl;
    if (!os.good())
    {
        FatalErrorInFunction
            << "Cannot write " << emptiedFile() << exit(FatalError);
    }
}


std::string Foam::demCoupling::demRestartFile::problem() const
{
    if (!isFile(file_))
    {
        if (isFile(emptiedFile()))
        {
            return "there is none: every DEM particle had left the domain by"
                " this time (" + emptiedFile().name() + "), and an empty DEM"
                " has no state to continue from; the particles' part of this"
                " run has ended";
        }
        if (exists(writingFile(), false, false))
        {
            return "it is missing; a partial " + writingFile().name()
                + " is there: the run was stopped while writing it";
        }
        return "it is missing (interDemFoam writes it at every write time;"
            " a folder without it was cut short or written by another"
            " program)";
    }
    if (!isFile(checkFile()))
    {
        return "its check file " + checkFile().name() + " is missing: the"
            " write of this time did not complete";
    }
    const HashTable<std::string> check(readCheck(checkFile()));
    for (const char* key : {"time", "size", "sha1", "particles"})
    {
        if (!check.found(key))
        {
            return "its check file " + checkFile().name() + " lacks '"
                + key + "'";
        }
    }
    if (check["time"] != timeName_)
    {
        return "its check file says it belongs to t = " + check["time"]
            + " s, not t = " + timeName_ + " s";
    }
    const std::string size(std::to_string(Foam::fileSize(file_)));
    if (check["size"] != size)
    {
        return "it has " + size + " bytes where " + check["size"]
            + " were written (damaged or cut short)";
    }
    if (check["sha1"] != fileSha1(file_))
    {
        return "its SHA-1 differs from the one written (the file was"
            " changed after it was written)";
    }
    return std::string();
}


void Foam::demCoupling::demRestartFile::addOption()
{
    argList::addBoolOption
    (
        "restartFromLastComplete",
        "when the start time's DEM state is damaged or missing, start from"
        " the latest earlier complete write time (later time folders are"
        " renamed <time>.incomplete)"
    );
}


void Foam::demCoupling::demRestartFile::selectStartTime
(
    Time& runTime,
    const bool fromLastComplete
)
{
    if (runTime.value() <= 0)
    {
        return;
    }
    // Only a coupled case has a DEM state
    IOobject io
    (
        "couplingProperties", runTime.constant(), runTime,
        IOobject::MUST_READ, IOobject::NO_WRITE
    );
    if (!io.typeHeaderOk<IOdictionary>(true))
    {
        return;
    }

    const word startName(runTime.timeName());
    string why;
    instant lastComplete(0, "0");
    bool haveComplete = false;
    if (Pstream::master())
    {
        why = demRestartFile(runTime, startName).problem();
        if (!why.empty())
        {
            const instantList times(runTime.times());
            for (label i = times.size() - 1; i >= 0; --i)
            {
                if (times[i].value() < runTime.value() && times[i].value() > 0)
                {
                    if (demRestartFile(runTime, times[i].name()).problem().empty())
                    {
                        lastComplete = times[i];
                        haveComplete = true;
                        break;
                    }
                }
            }
        }
    }
    Pstream::scatter(why);
    if (why.empty())
    {
        Info<< "DEM: the DEM state of t = " << startName << " s is complete"
            << " (size and SHA-1 as written)" << endl;
        return;
    }
    scalar lastValue = lastComplete.value();
    word lastName = lastComplete.name();
    Pstream::scatter(lastValue);
    Pstream::scatter(lastName);
    Pstream::scatter(haveComplete);

    fileName file(demRestartFile(runTime, startName).file());
    Pstream::scatter(file);
    const word fallback(haveComplete ? lastName : word("0"));

    if (!fromLastComplete)
    {
        FatalErrorInFunction
            << "Cannot restart at t = " << startName << " s: the DEM state "
            << file << nl << "    " << why.c_str() << "." << nl
            << "    The latest complete write time is "
            << (haveComplete ? lastName : word("none (start from 0)")) << "."
            << nl << "    Restart from it with" << nl
            << "        interDemFoam -restartFromLastComplete" << nl
            << "    (time folders after it are renamed <time>.incomplete,"
            << " nothing is deleted), or set startFrom startTime;"
            << " startTime " << fallback << "; in system/controlDict."
            << exit(FatalError);
    }

    if (runTime.controlDict().getOrDefault<word>("startFrom", "") != "latestTime")
    {
        FatalErrorInFunction
            << "-restartFromLastComplete needs startFrom latestTime in "
            << "system/controlDict" << exit(FatalError);
    }

    // Rename every time folder after the last complete one (this rank's)
    const instantList times(runTime.times());
    for (const instant& t : times)
    {
        if (t.value() > lastValue)
        {
            const fileName dir(runTime.path()/t.name());
            fileName aside(dir + ".incomplete");
            for (label n = 1; exists(aside); ++n)
            {
                aside = dir + ".incomplete" + Foam::name(n);
            }
            if (!Foam::mv(dir, aside))
            {
                FatalErrorInFunction
                    << "Cannot rename " << dir << " to " << aside
                    << exit(FatalError);
            }
            Info<< "DEM: " << dir.name() << " is incomplete, renamed to "
                << aside.name() << endl;
        }
    }
    Info<< "DEM: the DEM state of t = " << startName << " s is not usable ("
        << why.c_str() << "); -restartFromLastComplete: starting from t = "
        << fallback << " s" << nl << endl;
}


// ************************************************************************* //
