#include "stepOptions.hpp"

namespace mpm {

const char* massMatrixName(MassMatrix m)
{
    return m == MassMatrix::consistent ? "consistent" : "lumped";
}

bool parseMassMatrix(const std::string& name, MassMatrix& m)
{
    if (name == "lumped") { m = MassMatrix::lumped; return true; }
    if (name == "consistent") { m = MassMatrix::consistent; return true; }
    return false;
}

const char* validMassMatrixNames() { return "lumped consistent"; }

const char* stressUpdateName(StressUpdate s)
{
    switch (s)
    {
        case StressUpdate::USF: return "USF";
        case StressUpdate::USL: return "USL";
        default: return "MUSL";
    }
}

bool parseStressUpdate(const std::string& name, StressUpdate& s)
{
    for (auto c : {StressUpdate::USF, StressUpdate::USL, StressUpdate::MUSL})
    {
        if (name == stressUpdateName(c)) { s = c; return true; }
    }
    return false;
}

const char* validStressUpdateNames() { return "USF USL MUSL"; }

const char* transferName(Transfer t)
{
    return t == Transfer::apic ? "APIC" : "PICFLIP";
}

bool parseTransfer(const std::string& name, Transfer& t)
{
    if (name == "PICFLIP" || name == "picFlip") { t = Transfer::picFlip; return true; }
    if (name == "APIC" || name == "apic") { t = Transfer::apic; return true; }
    return false;
}

const char* validTransferNames() { return "PICFLIP APIC"; }

} // namespace mpm
