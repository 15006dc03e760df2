// vtk_output.cpp: VTK XML writers for particle and rod frames (see vtk_output.h).
#include "io/vtk_output.h"

#include <fmt/format.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationStringKey.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt64Array.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>
#include <vtkXMLWriter.h>

#include <algorithm>
#include <array>
#include <filesystem>

#include "io/atomic_file.h"
#include "swarf/core/errors.h"
#include "swarf/state/mesh.h"

namespace swarf {
namespace {

// The array's unit as VTK's UNITS_LABEL information key, which the XML writers store with
// the array (ParaView shows it in the information panel).
void set_unit(vtkDataArray* a, const char* unit) {
  if (unit) a->GetInformation()->Set(vtkDataArray::UNITS_LABEL(), unit);
}

vtkNew<vtkDoubleArray> vector_array(const char* name, const std::vector<Vec3>& v, const char* unit = nullptr) {
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  set_unit(a, unit);
  a->SetNumberOfComponents(3);
  a->SetNumberOfTuples(static_cast<vtkIdType>(v.size()));
  for (std::size_t i = 0; i < v.size(); ++i) a->SetTypedTuple(static_cast<vtkIdType>(i), v[i].data());
  return a;
}

vtkNew<vtkDoubleArray> scalar_array(const char* name, const std::vector<double>& v, const char* unit = nullptr) {
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  set_unit(a, unit);
  a->SetNumberOfValues(static_cast<vtkIdType>(v.size()));
  for (std::size_t i = 0; i < v.size(); ++i) a->SetValue(static_cast<vtkIdType>(i), v[i]);
  return a;
}

// A field of the table (output_fields.h) as a point array: its name, unit, components and
// their names (the stress: ParaView's order for a symmetric tensor, XX, YY, ZZ, XY, YZ, XZ).
vtkNew<vtkDoubleArray> field_array(const OutputField& f, const std::vector<double>& values) {
  vtkNew<vtkDoubleArray> a;
  const std::string name(f.name), unit(f.unit);
  a->SetName(name.c_str());
  set_unit(a, unit.c_str());
  a->SetNumberOfComponents(f.components);
  std::size_t c = 0, start = 0;
  const std::string names(f.component_names);
  while (start < names.size()) {
    const std::size_t end = std::min(names.find(' ', start), names.size());
    a->SetComponentName(static_cast<vtkIdType>(c++), names.substr(start, end - start).c_str());
    start = end + 1;
  }
  const std::size_t n = values.size() / static_cast<std::size_t>(f.components);
  a->SetNumberOfTuples(static_cast<vtkIdType>(n));
  for (std::size_t i = 0; i < n; ++i)
    a->SetTypedTuple(static_cast<vtkIdType>(i), values.data() + i * static_cast<std::size_t>(f.components));
  return a;
}

// The frame's simulated time as the field data array TimeValue (s), which ParaView and VTK's
// readers take for the time of a file opened alone (the .pvd gives it to the series too).
void set_time(vtkDataSet* grid, double t) {
  vtkNew<vtkDoubleArray> time;
  time->SetName("TimeValue");
  set_unit(time, "s");
  time->SetNumberOfValues(1);
  time->SetValue(0, t);
  grid->GetFieldData()->AddArray(time);
}

vtkNew<vtkPoints> points_of(const Particles& p) {
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  pts->SetNumberOfPoints(static_cast<vtkIdType>(p.size()));
  for (std::size_t i = 0; i < p.size(); ++i) pts->SetPoint(static_cast<vtkIdType>(i), p.position[i].data());
  return pts;
}

// Cells of one type with 'per' points each, from a flat connectivity list.
void set_cells(vtkUnstructuredGrid* grid, int type, int per, const std::vector<vtkIdType>& conn) {
  const vtkIdType nc = static_cast<vtkIdType>(conn.size() / per);
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfValues(nc + 1);
  for (vtkIdType c = 0; c <= nc; ++c) offsets->SetValue(c, c * per);
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(conn.size()));
  for (std::size_t k = 0; k < conn.size(); ++k) connectivity->SetValue(static_cast<vtkIdType>(k), conn[k]);
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  grid->SetCells(type, cells);
}

// Every XML file is written in VTK's "binary" mode: each array base64-encoded inside its
// DataArray element, not in an appended section. ParaView 5.11 as Debian 12 ships it cannot read
// an appended section (raw or base64) longer than one parser buffer since expat 2.5.0-1+deb12u2
// (its fix of CVE-2023-52425 defers parsing, and that VTK's parser expects the section's start
// where it stopped); inline data reads in every ParaView and VTK. The cost is a third more bytes
// (docs/outputs.md). zlib at its fastest level: smaller frames for little time.
void configure(vtkXMLWriter* w) {
  w->SetDataModeToBinary();
  w->SetHeaderTypeToUInt64();
  w->SetCompressorTypeToZLib();
  w->SetCompressionLevel(1);
}

// VTK writes the file into memory and swarf writes it out, with the checks every file gets
// (write_text_atomic: close and fsync checked, renamed only when complete). VTK's own file
// error path is never taken: on a full disk its binary mode aborted the program with a double
// free (DiskFull.AFrameThatCannotBeWrittenStopsTheRunAndIsNotRenamed).
void write_xml(vtkXMLWriter* w, const std::string& path) {
  configure(w);
  w->WriteToOutputStringOn();
  if (w->Write() != 1 || w->GetErrorCode() != 0) throw OutputError("cannot write VTK file '" + path + "'");
  try {
    write_text_atomic(path, w->GetOutputString());
  } catch (const std::exception& e) {
    throw OutputError("cannot write VTK file '" + path + "' (disk full?): " + e.what());
  }
}

void write_grid(vtkUnstructuredGrid* grid, const std::string& path) {
  vtkNew<vtkXMLUnstructuredGridWriter> w;
  w->SetInputData(grid);
  write_xml(w, path);
}

}  // namespace

void write_vtp(const std::string& path, const TriangleMesh& mesh) {
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  for (const auto& v : mesh.vertices) pts->InsertNextPoint(v.data());
  vtkNew<vtkCellArray> tris;
  for (const auto& t : mesh.triangles) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    tris->InsertNextCell(3, ids);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(pts);
  poly->SetPolys(tris);
  vtkNew<vtkXMLPolyDataWriter> w;
  w->SetInputData(poly);
  write_xml(w, path);
}

double broken_fraction_of(const Rods& r, std::size_t i) {
  const int n = r.row_start[i + 1] - r.row_start[i];
  if (n == 0) return 0.0;
  const bool formed = r.formed.size() == r.size();
  int broken = 0, original = 0, intact = 0;
  for (std::int32_t e = r.row_start[i]; e < r.row_start[i + 1]; ++e) {
    const std::int32_t k = r.entries[e].rod;
    broken += r.intact[k] ? 0 : 1;
    intact += r.intact[k] ? 1 : 0;
    original += formed && r.formed[k] ? 0 : 1;
  }
  // With rods formed during the run (bond formation), the share of the particle's original
  // coordination it has lost: 1 - intact / original, at least 0.
  if (original == n) return double(broken) / n;
  return original > 0 ? std::max(0.0, 1.0 - double(intact) / original) : 0.0;
}

std::vector<double> broken_fraction_per_particle(const Particles& p, const Rods& r) {
  std::vector<double> out(p.size(), 0.0);
  for (std::size_t i = 0; i < p.size(); ++i) out[i] = broken_fraction_of(r, i);
  return out;
}

VtkSeries::VtkSeries(const std::string& dir, bool with_rods, bool with_orientations, std::vector<std::string> fields)
    : dir_(dir), with_rods_(with_rods), with_orientations_(with_orientations), fields_(std::move(fields)) {
  std::filesystem::create_directories(std::filesystem::path(dir) / "frames");
}

void VtkSeries::write_frame(double t, const Particles& p, const Rods& r, const std::vector<MeshBody>& meshes,
                            const ParticleFields* fields) {
  const std::size_t k = times_.size();
  mesh_names_.clear();
  for (const auto& mb : meshes) {
    TriangleMesh placed = mb.mesh;
    for (std::size_t v = 0; v < placed.vertices.size(); ++v) placed.vertices[v] = mb.vertex(static_cast<int>(v));
    write_vtp(fmt::format("{}/frames/mesh_{}_{:05d}.vtp", dir_, mb.name, k), placed);
    mesh_names_.push_back(mb.name);
  }
  auto pts = points_of(p);
  {
    vtkNew<vtkUnstructuredGrid> grid;
    grid->SetPoints(pts);
    std::vector<vtkIdType> conn(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) conn[i] = static_cast<vtkIdType>(i);
    set_cells(grid, VTK_VERTEX, 1, conn);
    // The table's rows (output_fields.h): the chosen ones and those always written.
    const FieldInput in{p, r, fields};
    for (const OutputField* f : output_fields_in_write_order()) {
      if (f->choice == FieldChoice::Chosen && !has_field(fields_, f->name)) continue;
      if (f->measured && !fields) continue;
      grid->GetPointData()->AddArray(field_array(*f, compute_output_field(*f, in)));
    }
    if (with_orientations_) {
      vtkNew<vtkDoubleArray> q;
      q->SetName("orientation");
      q->SetNumberOfComponents(4);
      q->SetNumberOfTuples(static_cast<vtkIdType>(p.size()));
      for (std::size_t i = 0; i < p.size(); ++i) q->SetTypedTuple(static_cast<vtkIdType>(i), p.orientation[i].data());
      grid->GetPointData()->AddArray(q);
      grid->GetPointData()->AddArray(vector_array("angular_velocity", p.omega, "rad/s"));
    }
    vtkNew<vtkIntArray> group;
    group->SetName("group");
    group->SetNumberOfValues(static_cast<vtkIdType>(p.size()));
    for (std::size_t i = 0; i < p.size(); ++i) group->SetValue(static_cast<vtkIdType>(i), p.group[i]);
    grid->GetPointData()->AddArray(group);
    vtkNew<vtkTypeInt64Array> id;  // (stable ids: a particle is followed across frames whatever its row)
    id->SetName("id");
    set_unit(id, "1");
    id->SetNumberOfValues(static_cast<vtkIdType>(p.size()));
    for (std::size_t i = 0; i < p.size(); ++i) id->SetValue(static_cast<vtkIdType>(i), p.id[i]);
    grid->GetPointData()->AddArray(id);
    set_time(grid, t);
    write_grid(grid, dir_ + "/" + particles_file(k));
  }
  if (with_rods_) {
    vtkNew<vtkUnstructuredGrid> grid;
    grid->SetPoints(pts);
    std::vector<vtkIdType> conn(2 * r.size());
    std::vector<double> shift(r.size()), stress(r.size()), strain(r.size());
    vtkNew<vtkUnsignedCharArray> state;
    state->SetName("state");
    state->SetNumberOfValues(static_cast<vtkIdType>(r.size()));
    for (std::size_t b = 0; b < r.size(); ++b) {
      conn[2 * b] = r.ends[b][0];
      conn[2 * b + 1] = r.ends[b][1];
      shift[b] = r.shift[b];
      stress[b] = r.intact[b] ? r.stress[b] : 0.0;
      Vec3 d = p.position[r.ends[b][1]] - p.position[r.ends[b][0]];
      periodic_.wrap(d);
      const double len = d.norm();
      strain[b] = (len - r.rest_length[b]) / r.rest_length[b];
      state->SetValue(static_cast<vtkIdType>(b), r.intact[b]);
    }
    set_cells(grid, VTK_LINE, 2, conn);
    grid->GetCellData()->AddArray(scalar_array("stress", stress, "Pa"));
    grid->GetCellData()->AddArray(scalar_array("strain", strain, "1"));
    grid->GetCellData()->AddArray(scalar_array("plastic_shift", shift, "1"));
    grid->GetCellData()->AddArray(state);
    set_time(grid, t);
    write_grid(grid, fmt::format("{}/frames/rods_{:05d}.vtu", dir_, k));
  }
  times_.push_back(t);
  write_pvd();
}

std::string VtkSeries::particles_file(std::size_t k) { return fmt::format("frames/particles_{:05d}.vtu", k); }

void VtkSeries::add_final_part(const std::string& name, const std::string& file) {
  final_parts_.emplace_back(name, file);
  write_pvd();
}

void VtkSeries::write_pvd() const {
  std::string
      x = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
          "  <Collection>\n";
  for (std::size_t k = 0; k < times_.size(); ++k) {
    x += fmt::format(
        "    <DataSet timestep=\"{}\" group=\"\" part=\"0\" name=\"particles\" "
        "file=\"frames/particles_{:05d}.vtu\"/>\n",
        times_[k], k);
    if (with_rods_)
      x += fmt::format(
          "    <DataSet timestep=\"{}\" group=\"\" part=\"1\" name=\"rods\" file=\"frames/rods_{:05d}.vtu\"/>\n",
          times_[k], k);
    for (std::size_t m = 0; m < mesh_names_.size(); ++m)
      x += fmt::format(
          "    <DataSet timestep=\"{}\" group=\"\" part=\"{}\" name=\"{}\" file=\"frames/mesh_{}_{:05d}.vtp\"/>\n",
          times_[k], m + 2, mesh_names_[m], mesh_names_[m], k);
    if (k + 1 == times_.size())
      for (std::size_t e = 0; e < final_parts_.size(); ++e)
        x += fmt::format("    <DataSet timestep=\"{}\" group=\"\" part=\"{}\" name=\"{}\" file=\"{}\"/>\n", times_[k],
                         mesh_names_.size() + 2 + e, final_parts_[e].first, final_parts_[e].second);
  }
  x += "  </Collection>\n</VTKFile>\n";
  write_text_atomic(dir_ + "/particles.pvd", x);
}

}  // namespace swarf
