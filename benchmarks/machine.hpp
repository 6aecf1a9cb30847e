// What every benchmark prints about the machine it ran on.
#pragma once
#include <fstream>
#include <string>
#include <sys/utsname.h>
#include <unistd.h>

namespace mpm::bench {

inline std::string cpuModel()
{
    std::ifstream f("/proc/cpuinfo");
    std::string line;
    while (std::getline(f, line))
    {
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    }
    return "unknown";
}

// "<cpu model>, <n> cores, <os> <release>"
inline std::string machine()
{
    utsname u;
    uname(&u);
    return cpuModel() + ", " + std::to_string(sysconf(_SC_NPROCESSORS_ONLN)) + " cores, "
        + u.sysname + " " + u.release;
}

} // namespace mpm::bench
