#include "stepOptions.hpp"
#include "../common/enumTable.hpp"

namespace mpm {

namespace
{
const auto massMatrices = enumTable<MassMatrix>({{MassMatrix::lumped, "lumped"}, {MassMatrix::consistent, "consistent"}});
const auto stressUpdates = enumTable<StressUpdate>
({{StressUpdate::USF, "USF"}, {StressUpdate::USL, "USL"}, {StressUpdate::MUSL, "MUSL"}});
// picFlip and apic: accepted aliases
const auto transfers = enumTable<Transfer>
({{Transfer::picFlip, "PICFLIP"}, {Transfer::apic, "APIC"}, {Transfer::picFlip, "picFlip"}, {Transfer::apic, "apic"}});
const std::string massMatrixList = massMatrices.validNames();
const std::string stressUpdateList = stressUpdates.validNames();
const std::string transferList = transfers.validNames();
}

const char* massMatrixName(MassMatrix m) { return massMatrices.name(m); }
bool parseMassMatrix(const std::string& name, MassMatrix& m) { return massMatrices.parse(name, m); }
const char* validMassMatrixNames() { return massMatrixList.c_str(); }

const char* stressUpdateName(StressUpdate s) { return stressUpdates.name(s); }
bool parseStressUpdate(const std::string& name, StressUpdate& s) { return stressUpdates.parse(name, s); }
const char* validStressUpdateNames() { return stressUpdateList.c_str(); }

const char* transferName(Transfer t) { return transfers.name(t); }
bool parseTransfer(const std::string& name, Transfer& t) { return transfers.parse(name, t); }
const char* validTransferNames() { return transferList.c_str(); }

} // namespace mpm
