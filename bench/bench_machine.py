"""The machine a run measures on: its description for docs/performance.md, the thread counts
used, and whether another busy process shares it (the load average). Standard library only."""

import os
import platform
import re
import subprocess
import time


def command_output(args):
    try:
        return subprocess.run(args, capture_output=True, text=True, timeout=20).stdout
    except (OSError, subprocess.SubprocessError):
        return ""



def machine_description(build):
    lscpu = {}
    for line in command_output(["lscpu"]).splitlines():
        key, _, value = line.partition(":")
        lscpu[key.strip()] = value.strip()
    mem = ""
    try:
        with open("/proc/meminfo") as f:
            for line in f:
                if line.startswith("MemTotal:"):
                    mem = f"{int(line.split()[1]) / 1024 / 1024:.1f} GiB"
    except OSError:
        pass
    compiler, build_type, flags = "", "", ""
    try:
        with open(os.path.join(build, "CMakeCache.txt")) as f:
            cache = dict(re.findall(r"^([A-Z_]+):[A-Z]+=(.*)$", f.read(), re.M))
        cxx = cache.get("CMAKE_CXX_COMPILER", "c++")
        compiler = (command_output([cxx, "--version"]).splitlines() or [cxx])[0]
        build_type = cache.get("CMAKE_BUILD_TYPE", "")
        flags = cache.get(f"CMAKE_CXX_FLAGS_{build_type.upper()}", "")
    except OSError:
        pass
    packages = []
    for pkg in ("libassimp-dev", "libopenmesh-dev", "libcgal-dev", "libosd-dev",
                "libegl-mesa0", "libosmesa6"):
        version = command_output(["dpkg-query", "-W", "-f=${Version}", pkg]).strip()
        if version:
            packages.append(f"{pkg} {version}")
    cores = lscpu.get("CPU(s)", str(os.cpu_count()))
    threads = lscpu.get("Thread(s) per core", "?")
    return [
        ("CPU", lscpu.get("Model name", platform.processor() or "unknown")),
        ("Logical CPUs", f"{cores} ({threads} thread(s) per core)"),
        ("Memory", mem),
        ("Kernel", f"{platform.system()} {platform.release()}"),
        ("Compiler", f"{compiler}; {build_type} ({flags})"),
        ("Anchor packages", ", ".join(packages)),
        ("Load average at start", " ".join(f"{x:.2f}" for x in os.getloadavg())),
    ]



def hardware_threads():
    """What MeshEdit's "all cores" is: std::thread::hardware_concurrency(), the online CPUs."""
    return os.cpu_count() or 1


def threads_row(all_threads):
    """The machine table's row naming the thread counts of the run."""
    return ("Threads", f"MeshEdit's rows at 1 thread (`MESHEDIT_THREADS=1`: the figure the "
            f"ratios and targets use) and at all {all_threads} threads (`MESHEDIT_THREADS=0`); "
            "OpenMesh, "
            "CGAL, OpenSubdiv Far, Assimp and meshoptimizer on 1 (each row's threads column); "
            "llvmpipe's draws on its own threads")


def load_1min():
    """The 1-minute load average (/proc/loadavg), or None where there is none."""
    try:
        with open("/proc/loadavg") as f:
            return float(f.read().split()[0])
    except (OSError, ValueError, IndexError):
        return None


def wait_for_quiet(max_load, settle_s, log, poll_s=5.0):
    """Waits up to `settle_s` seconds for the 1-minute load to fall to `max_load` (a build that
    just finished keeps it up for a minute or two: it decays with a time constant of 60 s).
    Returns the load seen last (None if unknown); above `max_load`, another process is busy."""
    load = load_1min()
    deadline = time.monotonic() + settle_s
    if load is not None and load > max_load:
        log(f"load average {load:.2f} > {max_load}: waiting up to {settle_s:.0f} s for the "
            "machine to settle")
    while load is not None and load > max_load and time.monotonic() < deadline:
        time.sleep(poll_s)
        load = load_1min()
    return load
