// The enums' names come from one table each (common/enumTable.hpp): every
// value survives name -> parse, the aliases parse, unknown names do not,
// and the valid-name lists (error messages, tests of bad input) read as
// they did before the tables.
#include "backend/backend.hpp"
#include "grid/boundary.hpp"
#include "step/stepOptions.hpp"
#include <gtest/gtest.h>
#include <string>

using namespace mpm;

TEST(EnumTable, RoundTripAliasesAndValidNames)
{
    for (auto m : {MassMatrix::lumped, MassMatrix::consistent})
    {
        MassMatrix x{};
        ASSERT_TRUE(parseMassMatrix(massMatrixName(m), x));
        EXPECT_EQ(x, m);
    }
    for (auto s : {StressUpdate::USF, StressUpdate::USL, StressUpdate::MUSL})
    {
        StressUpdate x{};
        ASSERT_TRUE(parseStressUpdate(stressUpdateName(s), x));
        EXPECT_EQ(x, s);
    }
    for (auto w : {WallType::noSlip, WallType::slip, WallType::friction, WallType::periodic, WallType::outlet,
                   WallType::inlet})
    {
        WallType x{};
        ASSERT_TRUE(parseWallType(wallTypeName(w), x));
        EXPECT_EQ(x, w);
    }
    for (auto b : {Backend::serial, Backend::openmp, Backend::cuda})
    {
        Backend x{};
        ASSERT_TRUE(parseBackend(backendName(b), x));
        EXPECT_EQ(x, b);
    }
    Transfer t{};
    ASSERT_TRUE(parseTransfer("apic", t));
    EXPECT_EQ(t, Transfer::apic);
    EXPECT_STREQ(transferName(t), "APIC");
    ShapeKind k{};
    ASSERT_TRUE(parseShape("CBS", k));
    EXPECT_EQ(k, ShapeKind::cubicBSpline);
    EXPECT_STREQ(shapeName(k), "cubicBSpline");
    StressUpdate unknown = StressUpdate::USL;
    EXPECT_FALSE(parseStressUpdate("usl", unknown));

    EXPECT_STREQ(validMassMatrixNames(), "lumped consistent");
    EXPECT_STREQ(validStressUpdateNames(), "USF USL MUSL");
    EXPECT_STREQ(validTransferNames(), "PICFLIP APIC");
    EXPECT_STREQ(validWallTypeNames(), "noSlip slip friction periodic outlet inlet");
    EXPECT_STREQ(validBackendNames(), "serial openmp cuda");
    EXPECT_STREQ(validShapeNames(), "linearHat quadraticBSpline cubicBSpline (or LH QBS CBS)");
}
