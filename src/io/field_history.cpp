// field_history.cpp: the frames' fields into results.h5 and the XDMF sidecar (see field_history.h).
#include "io/field_history.h"

#include <fmt/format.h>
#include <vtkDataArray.h>
#include <vtkInformation.h>
#include <vtkInformationStringKey.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkType.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cstdint>
#include <filesystem>

#include "io/h5file.h"
#include "io/vtk_output.h"
#include "swarf/core/errors.h"

namespace swarf {
namespace {

// The array's values, row by row, as doubles (exact: the frames' real arrays are float64).
std::vector<double> reals(vtkDataArray* a) {
  const vtkIdType n = a->GetNumberOfTuples();
  const int c = a->GetNumberOfComponents();
  std::vector<double> v(static_cast<std::size_t>(n) * c);
  for (vtkIdType i = 0; i < n; ++i)
    for (int k = 0; k < c; ++k) v[static_cast<std::size_t>(i) * c + k] = a->GetComponent(i, k);
  return v;
}

// An integer array's values (ids, groups: below 2^53, so exact through GetComponent's double).
std::vector<std::int64_t> integers(vtkDataArray* a) {
  const std::vector<double> d = reals(a);
  return std::vector<std::int64_t>(d.begin(), d.end());
}

bool is_integer(vtkDataArray* a) { return a->GetDataType() != VTK_DOUBLE && a->GetDataType() != VTK_FLOAT; }

std::string unit_of(vtkDataArray* a) {
  vtkInformation* info = a->GetInformation();
  return info && info->Has(vtkDataArray::UNITS_LABEL()) ? info->Get(vtkDataArray::UNITS_LABEL()) : "1";
}

}  // namespace

std::string history_group(std::size_t k) { return fmt::format("/frames/{:05d}", k); }

std::vector<HistoryFrame> write_field_history(H5File& f, const std::string& dir, const std::vector<double>& times) {
  std::vector<HistoryFrame> out;
  std::vector<double> written_times;
  for (std::size_t k = 0; k < times.size(); ++k) {
    const std::string path = dir + "/" + VtkSeries::particles_file(k);
    if (!std::filesystem::exists(path)) continue;
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    vtkUnstructuredGrid* g = reader->GetOutput();
    if (reader->GetErrorCode() != 0 || !g || !g->GetPoints())
      throw OutputError(fmt::format("cannot read the frame '{}' for the field history", path));
    HistoryFrame fr{k, times[k], static_cast<std::size_t>(g->GetNumberOfPoints()), {}};
    const std::string group = history_group(k);
    auto put = [&](const std::string& name, vtkDataArray* a, const std::string& unit) {
      const std::size_t c = static_cast<std::size_t>(a->GetNumberOfComponents());
      const std::string set = group + "/" + name;
      const bool integer = is_integer(a);
      if (integer)
        f.write(set, integers(a).data(), fr.points, c);
      else
        f.write(set, reals(a).data(), fr.points, c);
      f.describe(set, unit,
                 fmt::format("frame {} at t = {:.6g} s: {} of {} (docs/outputs.md)", k, times[k],
                             name == "position" ? std::string("the particles' centres") : "point array '" + name + "'",
                             VtkSeries::particles_file(k)));
      fr.arrays.push_back({name, unit, c, integer});
    };
    put("position", g->GetPoints()->GetData(), "m");
    vtkPointData* pd = g->GetPointData();
    for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
      if (vtkDataArray* arr = pd->GetArray(a); arr && arr->GetName()) put(arr->GetName(), arr, unit_of(arr));
    f.write_attribute(group, "time_s", times[k]);
    written_times.push_back(times[k]);
    out.push_back(std::move(fr));
  }
  if (!out.empty()) {
    f.write("/frame_time", written_times.data(), written_times.size());
    f.describe("/frame_time", "s", "the simulated time of each group under /frames, in their order");
  }
  return out;
}

std::string field_history_xdmf(const std::vector<HistoryFrame>& frames, const std::string& h5_file) {
  std::string
      x = "<?xml version=\"1.0\" ?>\n"
          "<!-- swarf's field history: the particles' frames in results.h5 as one time series "
          "(ParaView, VisIt; docs/outputs.md) -->\n"
          "<Xdmf Version=\"2.0\">\n  <Domain>\n"
          "    <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const HistoryFrame& fr : frames) {
    auto item = [&](const HistoryArray& a) {
      const std::string dims = a.components == 1 ? fmt::format("{}", fr.points)
                                                 : fmt::format("{} {}", fr.points, a.components);
      return fmt::format(
          "<DataItem Dimensions=\"{}\" NumberType=\"{}\" Precision=\"8\" Format=\"HDF\">{}:{}/{}</DataItem>", dims,
          a.integer ? "Int" : "Float", h5_file, history_group(fr.number), a.name);
    };
    x += fmt::format("      <Grid Name=\"frame_{:05d}\" GridType=\"Uniform\">\n", fr.number);
    x += fmt::format("        <Time Value=\"{:.17g}\"/>\n", fr.time);
    x += fmt::format("        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"{}\" NodesPerElement=\"1\"/>\n",
                     fr.points);
    for (const HistoryArray& a : fr.arrays) {
      if (a.name == "position") {
        x += "        <Geometry GeometryType=\"XYZ\">\n          " + item(a) + "\n        </Geometry>\n";
        continue;
      }
      // (Matrix keeps a tensor's or quaternion's components as the .vtu has them; XDMF's Tensor6
      // would reorder the symmetric tensor)
      const char* type = a.components == 1 ? "Scalar" : a.components == 3 ? "Vector" : "Matrix";
      x += fmt::format("        <Attribute Name=\"{}\" AttributeType=\"{}\" Center=\"Node\">\n          {}\n", a.name,
                       type, item(a));
      x += "        </Attribute>\n";
    }
    x += "      </Grid>\n";
  }
  x += "    </Grid>\n  </Domain>\n</Xdmf>\n";
  return x;
}

}  // namespace swarf
