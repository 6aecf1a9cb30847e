#!/usr/bin/env python3
"""I/O cost of the material points: for each size (cells per side n, 8
points per cell, n^3 cells) and each format, three MPM steps that each
write, then three restarts that only read (endTime = the last written
time). Prints, per format and rank count: the median write time and the
median read time (both as the solver logs them: the slowest rank, wall
clock; the files are in the page cache, as right after a run) and the bytes
on disk of one write time's points. The medians because the disk's
write-back makes single writes noisy (0.4 to 1.7 s for the same 2-rank HDF5
write of 1 M points, one after another).

Formats: OpenFOAM's lagrangian cloud with writeFormat ascii and binary
(pointOutput foam), and pointOutput hdf5 (one file, collective MPI-IO on 2
ranks). The 2-rank hdf5 row also restarts on 1 rank from the 2-rank file
(a different number of ranks: every point read and routed). No
compression is offered, so none is reported.
"""
import os
import platform
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
WORK = os.path.join(HERE, "work")


def sh(cmd, cwd, log):
    with open(os.path.join(cwd, log), "w") as f:
        r = subprocess.run(cmd, cwd=cwd, shell=True, stdout=f, stderr=subprocess.STDOUT)
    if r.returncode:
        sys.exit("failed: %s in %s (see %s)" % (cmd, cwd, log))
    return open(os.path.join(cwd, log)).read()


def setfoam(case, entry, value, dict_="system/controlDict"):
    subprocess.run(["foamDictionary", "-entry", entry, "-set", str(value),
                    os.path.join(case, dict_)], check=True, stdout=subprocess.DEVNULL)


def base_case(n):
    case = os.path.join(WORK, "base%d" % n)
    if os.path.isdir(os.path.join(case, "0", "lagrangian")):
        return case
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(os.path.join(HERE, "case"), case)
    bm = os.path.join(case, "system", "blockMeshDict")
    txt = open(bm).read().replace("(N N N)", "(%d %d %d)" % (n, n, n))
    open(bm, "w").write(txt)
    sh("blockMesh", case, "log.blockMesh")
    sh("mpmSetParticles", case, "log.mpmSetParticles")
    return case


def median(xs):
    return sorted(xs)[len(xs)//2]


def bytes_of(paths):
    total = 0
    for p in paths:
        for root, _, files in os.walk(p):
            total += sum(os.path.getsize(os.path.join(root, f)) for f in files)
    return total


def measure(n, fmt, ranks):
    case = os.path.join(WORK, "n%d_%s_%d" % (n, fmt, ranks))
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(base_case(n), case, ignore=shutil.ignore_patterns("processor*"))
    setfoam(case, "writeFormat", "binary" if fmt == "binary" else "ascii")
    setfoam(case, "pointOutput", "hdf5" if fmt == "hdf5" else "foam", "constant/mpmProperties")
    par = ""
    if ranks > 1:
        with open(os.path.join(case, "system", "decomposeParDict"), "w") as f:
            f.write("FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\n"
                    "numberOfSubdomains %d;\nmethod scotch;\n" % ranks)
        sh("decomposePar -force", case, "log.decomposePar")
        par = "mpirun -np %d " % ranks
    flag = " -parallel" if ranks > 1 else ""
    log = sh(par + "mpmFoam" + flag, case, "log.write")
    wrote = median([float(w) for w in re.findall(r"material points and the lattice fields in (\S+) s", log)])
    t = re.findall(r"^Time = (\S+)", log, re.M)[-1]
    if fmt == "hdf5":
        size = os.path.getsize(os.path.join(case, "HDF5", "materialPoints_%s.h5" % t))
    else:
        dirs = [os.path.join(case, t, "lagrangian")] + [
            os.path.join(case, p, t, "lagrangian") for p in os.listdir(case) if p.startswith("processor")]
        size = bytes_of([d for d in dirs if os.path.isdir(d)])
    read = median([float(re.search(r"Read the material points in (\S+) s",
                                   sh(par + "mpmFoam" + flag, case, "log.read")).group(1)) for _ in range(3)])
    row = [wrote, read, size]
    if fmt == "hdf5" and ranks > 1:
        # Restart on 1 rank from the 2-rank file: every point read and routed
        setfoam(case, "startFrom", "startTime")
        setfoam(case, "startTime", t)
        row.append(median([float(re.search(r"Read the material points in (\S+) s",
                                           sh("mpmFoam", case, "log.readOnOne")).group(1)) for _ in range(3)]))
    shutil.rmtree(case, ignore_errors=True)
    return row


def main():
    sizes = [int(a) for a in sys.argv[1:]] or [50]
    os.makedirs(WORK, exist_ok=True)
    cpu = [l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")]
    print("I/O of the material points (benchmarks/ioFormats)")
    print("machine: %s, %d cores, %s; %s" % (cpu[0] if cpu else platform.processor(), os.cpu_count(),
          platform.platform(), time.strftime("%Y-%m-%d")))
    print("%-9s %-8s %5s %10s %10s %10s %9s" % ("points", "format", "ranks", "write s", "read s", "MB", "B/point"))
    for n in sizes:
        points = 8*n**3
        for fmt in ("ascii", "binary", "hdf5"):
            for ranks in (1, 2):
                row = measure(n, fmt, ranks)
                print("%-9d %-8s %5d %10.2f %10.2f %10.1f %9.0f" % (points, fmt, ranks, row[0], row[1],
                      row[2]/1e6, row[2]/points), flush=True)
                if len(row) > 3:
                    print("%-9d %-8s %5s %10s %10.2f %10s %9s" % (points, fmt, "2->1", "", row[3], "", ""), flush=True)
        shutil.rmtree(os.path.join(WORK, "base%d" % n), ignore_errors=True)


if __name__ == "__main__":
    main()
