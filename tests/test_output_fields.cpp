// test_output_fields.cpp: the table of the per-particle output fields (io/output_fields.h) is
// complete, its consumers read it (the key's allowed values, the frames' order), and
// docs/outputs.md holds its generated table.
#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkInformation.h>
#include <vtkInformationStringKey.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "io/h5file.h"
#include "io/output_fields.h"
#include "scenes/tiny_uniaxial.h"
#include "setup/case_config.h"
#include "setup/case_keys.h"
#include "swarf/core/errors.h"
#include "test_helpers.h"

namespace swarf {
namespace {

const std::string kOutputsDoc = std::string(SWARF_SOURCE_DIR) + "/docs/outputs.md";

TEST(OutputFields, DocumentHoldsTheGeneratedTable) {
  const std::string doc = test::read_file(kOutputsDoc);
  ASSERT_FALSE(doc.empty()) << kOutputsDoc;
  EXPECT_TRUE(update_output_fields_doc(doc) == doc)
      << "regenerating the fields' table changes " << kOutputsDoc
      << " (edit src/io/output_fields.cpp, then run 'swarf case fields --update docs/outputs.md'); the table:\n"
      << output_fields_markdown();
  EXPECT_THROW(update_output_fields_doc("no markers"), InputError);
}

TEST(OutputFields, EveryRowIsComplete) {
  std::set<std::string> names;
  for (const OutputField& f : output_fields()) {
    const std::string name(f.name);
    EXPECT_TRUE(names.insert(name).second) << name << " twice";
    EXPECT_FALSE(f.unit.empty()) << name;
    EXPECT_FALSE(f.description.empty()) << name;
    EXPECT_TRUE(f.compute != nullptr) << name;
    EXPECT_TRUE(f.components == 1 || f.components == 3 || f.components == 6) << name;
    if (!f.component_names.empty())
      EXPECT_EQ(std::count(f.component_names.begin(), f.component_names.end(), ' ') + 1, f.components) << name;
    EXPECT_EQ(find_output_field(f.name), &f);
  }
  for (const FixedArrayDoc& a : output_fixed_arrays())
    EXPECT_TRUE(names.insert(std::string(a.name)).second) << a.name << " is both a row and a fixed array";
  EXPECT_EQ(find_output_field("damage"), nullptr);
}

// output.fields' allowed values and default are the table's chosen rows, in table order.
TEST(OutputFields, TheKeyOffersTheTablesRows) {
  const std::vector<std::string> names = output_field_names();
  EXPECT_EQ(OutputSettings{}.fields, names);
  EXPECT_EQ(std::vector<std::string>(names.begin(), names.begin() + 10),
            (std::vector<std::string>{"velocity", "displacement", "broken_fraction", "stress", "von_mises_stress",
                                      "hydrostatic_stress", "plastic_strain", "peeq", "peeq_rate", "temperature"}));
  for (const auto& k : output_keys())
    if (k.name == "fields") {
      EXPECT_EQ(std::vector<std::string>(k.choices.begin(), k.choices.end()), names);
    }
  EXPECT_TRUE(needs_particle_fields({"von_mises_stress"}));
  EXPECT_FALSE(needs_particle_fields({"velocity", "peeq"}));
  EXPECT_TRUE(needs_plastic_strain_window({"peeq_rate"}));
  EXPECT_FALSE(needs_plastic_strain_window({"stress", "temperature"}));
}

// The frames write the rows in the order their arrays had before the table (tests and readers
// that list a frame's arrays keep seeing them so); a new row comes after its kind's.
TEST(OutputFields, TheFramesKeepTheirArraysOrder) {
  std::vector<std::string> order;
  for (const OutputField* f : output_fields_in_write_order()) order.emplace_back(f->name);
  const std::vector<std::string> before{
      "velocity",  "displacement", "radius",           "broken_fraction",    "temperature",   "peeq",
      "peeq_rate", "stress",       "von_mises_stress", "hydrostatic_stress", "plastic_strain"};
  std::vector<std::string> old_ones;
  for (const std::string& n : order)
    if (std::find(before.begin(), before.end(), n) != before.end()) old_ones.push_back(n);
  EXPECT_EQ(old_ones, before);
}

// The coordination number, added as one row of the table: a run writes it to the frames and
// results.h5 (and so to the field history), with its unit, and it counts the intact rods.
TEST(OutputFields, CoordinationReachesTheFramesAndResults) {
  test::TempDir dir("coordination");
  test::write_file(dir / "tiny.toml", test::kTinyUniaxial);
  const auto r = test::run_command(std::string(SWARF_BINARY) + " run " + (dir / "tiny.toml") + " --out " +
                                   (dir / "out") + " --set integrator.end_time=2e-5 --set output.plots=false");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName((dir / "out/frames/particles_00001.vtu").c_str());
  reader->Update();
  vtkDataArray* a = reader->GetOutput()->GetPointData()->GetArray("coordination");
  ASSERT_NE(a, nullptr);
  ASSERT_TRUE(a->GetInformation()->Has(vtkDataArray::UNITS_LABEL()));
  EXPECT_STREQ(a->GetInformation()->Get(vtkDataArray::UNITS_LABEL()), "1");
  EXPECT_EQ(a->GetNumberOfComponents(), 1);
  double lo = 1e9, hi = -1e9;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i) {
    lo = std::min(lo, a->GetComponent(i, 0));
    hi = std::max(hi, a->GetComponent(i, 0));
  }
  EXPECT_EQ(hi, 12.0) << "an interior particle of the FCC lattice";
  EXPECT_GE(lo, 0.0);
  EXPECT_LT(lo, 12.0) << "the block's surface particles have fewer";

  H5File h5(dir / "out/results.h5", H5File::Mode::Read);
  ASSERT_TRUE(h5.has("/particles/coordination"));
  EXPECT_EQ(h5.dataset_attribute("/particles/coordination", "unit"), "1");
  EXPECT_EQ(h5.dataset_attribute("/particles/coordination", "description"),
            "coordination number: the particle's intact rods");
  std::size_t rows = 0, cols = 0, radius_rows = 0;
  const std::vector<double> c = h5.read_doubles("/particles/coordination", rows, cols);
  EXPECT_EQ(cols, 1u);
  h5.read_doubles("/particles/radius", radius_rows, cols);
  ASSERT_EQ(rows, radius_rows);
  EXPECT_EQ(*std::max_element(c.begin(), c.end()), 12.0);
  EXPECT_TRUE(h5.has("/frames/00001/coordination")) << "the field history copies it";

  // Left out when output.fields does not name it.
  const auto some = test::run_command(std::string(SWARF_BINARY) + " run " + (dir / "tiny.toml") + " --out " +
                                      (dir / "some") +
                                      " --set integrator.end_time=2e-5 --set output.plots=false "
                                      "--set 'output.fields=[\"velocity\"]'");
  ASSERT_EQ(some.exit_code, 0) << some.output;
  H5File h5some(dir / "some/results.h5", H5File::Mode::Read);
  EXPECT_FALSE(h5some.has("/particles/coordination"));
}

}  // namespace
}  // namespace swarf
