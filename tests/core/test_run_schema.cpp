// The run schema (core/io/run_schema.h) is the one list of metric columns: the writer writes every
// column with its units and description, the checked reader reads every column back, and
// docs/output-format.md describes each exactly as the table does.
#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <string>

#include "core/io/run_reader.h"
#include "core/io/run_schema.h"
#include "core/io/run_writer.h"
#include "tests/support/hdf5_reader.h"
#include "tests/support/markdown_table.h"
#include "tests/support/scratch_directory.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

TEST(RunSchema, NamesAreUniqueAndEveryFieldOfMetricsIsAColumn) {
    std::set<std::string> names;
    for (const MetricColumn& c : metric_columns) {
        EXPECT_TRUE(names.insert(c.name).second) << c.name;
        EXPECT_NE(c.real == nullptr, c.count == nullptr) << c.name << ": exactly one field";
        EXPECT_EQ(find_metric_column(c.name), &c);
    }
    // Every field set to a distinct value comes back through its column once.
    Metrics m;
    double v = 1;
    for (const MetricColumn& c : metric_columns) c.assign(m, v++);
    v = 1;
    for (const MetricColumn& c : metric_columns) EXPECT_EQ(c.value(m), v++) << c.name;
    EXPECT_EQ(sizeof(Metrics), metric_column_count * 8) << "a field of Metrics that is no column of the schema";
    EXPECT_EQ(find_metric_column("wall_penetration"), nullptr);
}

TEST(RunSchema, DocsDescribeEveryColumnAsTheTableDoes) {
    const auto rows = test::markdown_table_after("docs/output-format.md", "### Metrics");
    ASSERT_EQ(rows.size(), metric_column_count) << "docs/output-format.md: one row per column of core/io/run_schema.h";
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const MetricColumn& c = metric_columns[k];
        ASSERT_EQ(rows[k].size(), 3u);
        EXPECT_EQ(rows[k][0], c.name) << "row " << k;
        EXPECT_EQ(rows[k][1], c.units) << c.name;
        EXPECT_EQ(rows[k][2], c.description) << c.name;
    }
    // The layout tree lists each with its stored type.
    const std::string page = test::read_source_file("docs/output-format.md");
    for (const MetricColumn& c : metric_columns) {
        const std::regex line(std::string("── ") + c.name + " +" + (c.integer() ? "int64" : "float64"));
        EXPECT_TRUE(std::regex_search(page, line)) << c.name << " missing from the layout tree, or of another type";
    }
}

TEST(RunSchema, WriterWritesAndReaderReadsEveryColumn) {
    test::ScratchDirectory dir;
    const std::string path = dir.file("run.h5");
    const ParticleState<double> disks = test::make_state({{1, 2, 0.5, -0.25, 0.5, 2}, {4, 5, -1, 1, 0.25, 3}});
    Metrics rows[2];
    for (int k = 0; k < 2; ++k) {
        double v = 10 * k;
        for (const MetricColumn& c : metric_columns) c.assign(rows[k], v++);
        rows[k].nonfinite = k;  // at most the 2 disks, as the reader requires
    }
    {
        RunWriter writer(path, false);
        writer.write_attributes({{"backend", "step"}});
        writer.write_particles(disks);
        for (const Metrics& m : rows) writer.append(m, disks);
        writer.write_stats(SolverStats{});
        writer.commit();
    }
    const test::Hdf5File raw(path);  // the file as HDF5 stores it, not through the reader
    for (const MetricColumn& c : metric_columns) {
        const std::string dataset = std::string("/metrics/") + c.name;
        ASSERT_TRUE(raw.has(dataset)) << c.name;
        EXPECT_EQ(raw.string_attribute(dataset, "units"), c.units);
        EXPECT_EQ(raw.string_attribute(dataset, "description"), c.description);
    }
    const RunFile run(path);
    ASSERT_EQ(run.output_count(), 2u);
    for (int k = 0; k < 2; ++k) {
        const Metrics back = run.metrics_at(std::size_t(k));
        for (const MetricColumn& c : metric_columns) {
            EXPECT_EQ(c.value(back), c.value(rows[k])) << c.name;
            EXPECT_EQ(run.metric(c.name)[std::size_t(k)], c.value(rows[k])) << c.name;
        }
    }
}

}  // namespace
}  // namespace collide
