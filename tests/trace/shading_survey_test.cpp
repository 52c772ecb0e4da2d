// The shading survey (shading_survey.h) through the command-line tool: POV-Ray and
// `mirage trace --no-atmosphere` at 160x120, PSNR >= 35 dB.
//
// ShadingSurvey.DISABLED_Everything renders every case and writes build/shading_survey/
// results.csv and table.md (docs/shading.md's table):
//   build/mirage_tests --gtest_also_run_disabled_tests
//       --gtest_filter=ShadingSurvey.DISABLED_Everything
#include "shading_survey.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>

namespace mirage {
namespace {

using namespace mirage::testing;

constexpr int kJobs = 4;

// Every pattern and warp, every 48th declaration of each include file (the in-process
// PovIncludeMaterials tests show all of them), and the refusals of the patterns the tracer
// does not evaluate, which must name the pattern and its place.
TEST(ShadingSurvey, PatternsWarpsAndIncludeMaterialsThroughTheTool) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    constexpr int kIncludeStride = 48;
    std::vector<SurveyCase> cases;
    std::map<std::string, int> seen;
    for (SurveyCase& c : survey_cases()) {
        const bool include = c.group.find(".inc") != std::string::npos;
        if (include && seen[c.group]++ % kIncludeStride != 0) continue;
        cases.push_back(std::move(c));
    }
    ASSERT_GE(cases.size(), 75u);
    const auto dir = test_dir("shading_survey", "cases");
    const auto results = run_survey(cases, dir, kJobs);
    int matched = 0;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const SurveyCase& c = cases[i];
        const SurveyResult& r = results[i];
        if (c.group == "patterns (refused)") {
            EXPECT_EQ(r.status, "trace_failed") << c.name;
            EXPECT_NE(r.message.find("scene.pov:"), std::string::npos)
                << c.name << ": " << r.message;
            EXPECT_NE(r.message.find("unsupported pattern '" + c.name + "'"), std::string::npos)
                << c.name << ": " << r.message;
            continue;
        }
        EXPECT_EQ(r.status, "match")
            << c.group << " " << c.name << ": " << r.message << " (" << r.psnr << " dB, "
            << (dir / std::to_string(i)).string() << ")";
        matched += r.status == "match";
    }
    std::printf("%zu cases through mirage trace --no-atmosphere, %d matching POV-Ray\n",
                cases.size(), matched);
}

TEST(ShadingSurvey, DISABLED_Everything) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const auto cases = survey_cases();
    const std::filesystem::path out = std::filesystem::path(MIRAGE_BINARY_DIR) / "shading_survey";
    const auto results = run_survey(cases, out / "cases", kJobs);
    std::ofstream csv(out / "results.csv");
    csv << "group,case,status,psnr_db,message\n";
    struct Counts {
        int cases = 0, match = 0, identical = 0, differ = 0, trace_failed = 0, pov_failed = 0;
        double lowest = INFINITY;  // the lowest PSNR of the matches
    };
    std::vector<std::string> order;
    std::map<std::string, Counts> counts;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const SurveyResult& r = results[i];
        std::string message = r.message;
        for (char& ch : message) {
            if (ch == ',' || ch == '"') ch = ';';
        }
        char psnr[32] = "";
        if (r.status == "match" || r.status == "differ")
            std::snprintf(psnr, sizeof psnr, "%.1f", r.psnr);
        csv << cases[i].group << "," << cases[i].name << "," << r.status << "," << psnr << ","
            << message << "\n";
        if (!counts.count(cases[i].group)) order.push_back(cases[i].group);
        Counts& c = counts[cases[i].group];
        ++c.cases;
        c.match += r.status == "match";
        if (r.status == "match") {
            c.identical += std::isinf(r.psnr);
            c.lowest = std::min(c.lowest, r.psnr);
        }
        c.differ += r.status == "differ";
        c.trace_failed += r.status == "trace_failed";
        c.pov_failed += r.status == "pov_failed";
    }
    std::ofstream md(out / "table.md");
    md << "| group | cases | match (>= 35 dB) | of them identical | lowest match (dB) | differ | "
          "refused by mirage | refused by POV-Ray |\n"
          "|---|---:|---:|---:|---:|---:|---:|---:|\n";
    const auto lowest = [](double db) {
        char text[32] = "";
        if (std::isfinite(db)) std::snprintf(text, sizeof text, "%.1f", db);
        return std::string(text);
    };
    Counts all;
    for (const std::string& g : order) {
        const Counts& c = counts[g];
        md << "| " << g << " | " << c.cases << " | " << c.match << " | " << c.identical << " | "
           << lowest(c.lowest) << " | " << c.differ << " | " << c.trace_failed << " | "
           << c.pov_failed << " |\n";
        all.cases += c.cases;
        all.match += c.match;
        all.identical += c.identical;
        all.lowest = std::min(all.lowest, c.lowest);
        all.differ += c.differ;
        all.trace_failed += c.trace_failed;
        all.pov_failed += c.pov_failed;
    }
    md << "| all | " << all.cases << " | " << all.match << " | " << all.identical << " | "
       << lowest(all.lowest) << " | " << all.differ << " | " << all.trace_failed << " | "
       << all.pov_failed << " |\n\n";
    md << "| group | case | status | PSNR (dB) | message |\n|---|---|---|---:|---|\n";
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const SurveyResult& r = results[i];
        if (r.status == "match") continue;
        char psnr[32] = "";
        if (r.status == "differ") std::snprintf(psnr, sizeof psnr, "%.1f", r.psnr);
        md << "| " << cases[i].group << " | " << cases[i].name << " | " << r.status << " | " << psnr
           << " | " << r.message << " |\n";
    }
    std::printf("%d cases: %d match, %d differ, %d refused by mirage, %d by POV-Ray\n", all.cases,
                all.match, all.differ, all.trace_failed, all.pov_failed);
}

}  // namespace
}  // namespace mirage
