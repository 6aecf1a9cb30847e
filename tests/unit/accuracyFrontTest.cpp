// Accuracy front (accuracy/accuracyFront.hpp): reading the results CSV of
// bin/mpmAccuracyCost and finding the case's configuration in it -- the
// end-of-run "Expected error" line. A made-up front of 5 runs: QBS 48 is
// dominated by CBS 48 (dearer and less accurate), CBS 24 is unstable (so CBS
// 48 is fragile), CBS 96 is the reference (never quoted).
#include "accuracy/accuracyFront.hpp"
#include <gtest/gtest.h>
#include <map>
#include <stdexcept>
#include <string>

using namespace mpm::accuracy;

namespace {

const std::string csv =
    "# cpu: test\n"
    "# parameters: shape cells\n"
    "# error: max pore-pressure error\n"
    "shape,cells,reference,status,fragile,failure,error,solverTime,"
    "constant/mpmProperties:shapeFunction,system/blockMeshDict:h,"
    "system/mpmSetParticlesDict:regions/soil/max\n"
    "QBS,24,0,ok,0,,0.04,0.5,quadraticBSpline,0.005,(0.005 0.1 0.005)\n"
    "QBS,48,0,ok,0,,0.03,2.0,quadraticBSpline,0.0025,(0.0025 0.1 0.0025)\n"
    "CBS,48,0,ok,1,,0.02,1.5,cubicBSpline,0.0025,(0.0025 0.1 0.0025)\n"
    "CBS,24,0,unstable,0,\"non-finite, step 3\",nan,0.1,cubicBSpline,0.005,(0.005 0.1 0.005)\n"
    "CBS,96,1,ok,0,,0.001,9,cubicBSpline,0.00125,(0.00125 0.1 0.00125)\n";

// A case whose dictionaries hold these values
EntryLookup caseWith(std::map<std::string, std::string> values)
{
    return [values](const std::string& file, const std::string& entry) -> std::optional<std::string>
    {
        const auto it = values.find(file + ":" + entry);
        if (it == values.end()) return std::nullopt;
        return it->second;
    };
}

} // namespace

TEST(AccuracyFront, ParsesHeaderColumnsAndQuotedFields)
{
    const AccuracyFront f = parseAccuracyFront(csv);
    EXPECT_EQ(f.errorName, "max pore-pressure error");
    ASSERT_EQ(f.parameters.size(), 2u);
    EXPECT_EQ(f.parameters[1], "cells");
    ASSERT_EQ(f.entryColumns.size(), 3u);
    ASSERT_EQ(f.runs.size(), 5u);
    EXPECT_EQ(f.runs[3].columns.at("failure"), "non-finite, step 3");
    EXPECT_FALSE(f.runs[3].usable);   // unstable
    EXPECT_FALSE(f.runs[4].usable);   // the reference run
    EXPECT_TRUE(f.runs[0].usable);
    EXPECT_DOUBLE_EQ(f.runs[2].error, 0.02);
    EXPECT_TRUE(f.runs[2].fragile);    // its family was unstable (the CBS 24 run)
    EXPECT_FALSE(f.runs[0].fragile);
    EXPECT_EQ(describe(f, f.runs[2]), "shape CBS, cells 48");
}

TEST(AccuracyFront, SameValueComparesTokensAndNumbers)
{
    EXPECT_TRUE(sameValue("0.0025", "2.5e-3"));
    EXPECT_TRUE(sameValue("(0.0025 0.1 0.0025)", "( 0.0025 0.1 0.0025 )"));
    EXPECT_TRUE(sameValue("0.00833333333333", "0.00833333"));   // printed back to 6 digits
    EXPECT_FALSE(sameValue("0.0025", "0.0026"));
    EXPECT_FALSE(sameValue("(0.0025 0.1)", "(0.0025 0.1 0.0025)"));
    EXPECT_FALSE(sameValue("cubicBSpline", "quadraticBSpline"));
    EXPECT_FALSE(sameValue("auto", "24"));
}

TEST(AccuracyFront, FindsTheCaseConfigurationOnTheFront)
{
    const AccuracyFront f = parseAccuracyFront(csv);
    const Expected e = expectedError(f, caseWith({
        {"constant/mpmProperties:shapeFunction", "cubicBSpline"},
        {"system/blockMeshDict:h", "0.0025"},
        {"system/mpmSetParticlesDict:regions/soil/max", "( 0.0025 0.1 0.0025 )"}}));
    ASSERT_NE(e.run, nullptr);
    EXPECT_DOUBLE_EQ(e.run->error, 0.02);
    EXPECT_TRUE(e.onFront);
    EXPECT_EQ(e.usableRuns, 3);
}

TEST(AccuracyFront, DominatedConfigurationNamesTheCheaperBetterRun)
{
    const AccuracyFront f = parseAccuracyFront(csv);
    const Expected e = expectedError(f, caseWith({
        {"constant/mpmProperties:shapeFunction", "quadraticBSpline"},
        {"system/blockMeshDict:h", "0.0025"},
        {"system/mpmSetParticlesDict:regions/soil/max", "(0.0025 0.1 0.0025)"}}));
    ASSERT_NE(e.run, nullptr);
    EXPECT_DOUBLE_EQ(e.run->error, 0.03);
    EXPECT_FALSE(e.onFront);
    ASSERT_NE(e.cheaperAsGood, nullptr);
    EXPECT_DOUBLE_EQ(e.cheaperAsGood->error, 0.02);   // CBS 48: 1.5 s < 2 s, 0.02 < 0.03
}

TEST(AccuracyFront, UnmeasuredFailedReferenceOrMissingEntriesMatchNothing)
{
    const AccuracyFront f = parseAccuracyFront(csv);
    // not in the sweep
    EXPECT_EQ(expectedError(f, caseWith({
        {"constant/mpmProperties:shapeFunction", "cubicBSpline"},
        {"system/blockMeshDict:h", "0.003"},
        {"system/mpmSetParticlesDict:regions/soil/max", "(0.003 0.1 0.003)"}})).run, nullptr);
    // the unstable run and the reference run are never quoted
    EXPECT_EQ(expectedError(f, caseWith({
        {"constant/mpmProperties:shapeFunction", "cubicBSpline"},
        {"system/blockMeshDict:h", "0.005"},
        {"system/mpmSetParticlesDict:regions/soil/max", "(0.005 0.1 0.005)"}})).run, nullptr);
    EXPECT_EQ(expectedError(f, caseWith({
        {"constant/mpmProperties:shapeFunction", "cubicBSpline"},
        {"system/blockMeshDict:h", "0.00125"},
        {"system/mpmSetParticlesDict:regions/soil/max", "(0.00125 0.1 0.00125)"}})).run, nullptr);
    // an entry the case lacks
    EXPECT_EQ(expectedError(f, caseWith({
        {"constant/mpmProperties:shapeFunction", "cubicBSpline"},
        {"system/blockMeshDict:h", "0.0025"}})).run, nullptr);
}

TEST(AccuracyFront, BadFilesAreNamed)
{
    try
    {
        parseAccuracyFront("# only a header\n");
        FAIL() << "no throw";
    }
    catch (const std::runtime_error& e)
    {
        EXPECT_STREQ(e.what(), "no header row");
    }
    try
    {
        parseAccuracyFront("a,b,status,solverTime\n1,2,ok,3\n");
        FAIL() << "no throw";
    }
    catch (const std::runtime_error& e)
    {
        EXPECT_STREQ(e.what(), "no 'error' column in the header row");
    }
    try
    {
        parseAccuracyFront("error,solverTime,status\n1,2\n");
        FAIL() << "no throw";
    }
    catch (const std::runtime_error& e)
    {
        EXPECT_STREQ(e.what(), "a row has 2 fields, the header 3");
    }
}
