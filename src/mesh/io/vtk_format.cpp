#include "mesh/io/vtk_format.hpp"

#include <charconv>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iomanip>

#include "core/atomic_write.hpp"
#include "core/error.hpp"
#include "mesh/node_ordering.hpp"

namespace aster::mesh {

namespace {

int vtkType(CellType t) {
  switch (t) {
    case CellType::POI1: return 1;
    case CellType::SEG2: return 3;
    case CellType::SEG3: return 21;
    case CellType::SEG4: return 35;
    case CellType::TRIA3: return 5;
    case CellType::TRIA6: return 22;
    case CellType::TRIA7: return 34;
    case CellType::QUAD4: return 9;
    case CellType::QUAD8: return 23;
    case CellType::QUAD9: return 28;
    case CellType::TETRA4: return 10;
    case CellType::TETRA10: return 24;
    case CellType::PENTA6: return 13;
    case CellType::PENTA15: return 26;
    case CellType::PENTA18: return 32;
    case CellType::PYRAM5: return 14;
    case CellType::PYRAM13: return 27;
    case CellType::HEXA8: return 12;
    case CellType::HEXA20: return 25;
    case CellType::HEXA27: return 29;
  }
  return 0;
}

// The shortest text that reads back as the same double (std::to_chars): a study
// writes every converged instant, and iostream formatting was most of that time.
void appendNumber(std::string& out, double v) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, v).ptr;
  out.append(buffer, end);
  out += ' ';
}

// A binary DataArray's content: the byte count (UInt32, the default header
// type) then the values, little-endian as the file declares, in base64.
std::string base64Block(const std::vector<double>& values) {
  static_assert(sizeof(double) == 8);
  std::string bytes(4 + values.size() * 8, '\0');
  const std::uint32_t size = static_cast<std::uint32_t>(values.size() * 8);
  for (int b = 0; b < 4; ++b) bytes[b] = static_cast<char>((size >> (8 * b)) & 0xff);
  if (!values.empty()) std::memcpy(&bytes[4], values.data(), values.size() * 8);
  static const char* const kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t v = 0;
    for (std::size_t k = 0; k < 3; ++k)
      v = (v << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    for (std::size_t k = 0; k < 4; ++k) out += k <= n ? kDigits[(v >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

std::string baseName(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

void writeVtu(const Mesh& mesh, const std::string& path, const std::vector<NodalField>& fields,
              const std::vector<CellValues>& cellFields) {
  for (const auto& f : cellFields) checkCellValues(mesh, f, "VTK writer");
  for (const auto& f : fields)
    if (f.components.empty() || f.values.size() != f.components.size() * static_cast<std::size_t>(mesh.nodeCount()))
      throw Error("VTK writer: field '" + f.name + "' has " + std::to_string(f.values.size()) + " values, expected " +
                  std::to_string(mesh.nodeCount()) + " nodes x " + std::to_string(f.components.size()) + " components");
  OutputFile file(path);
  std::ostream& out = file.stream();
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
      << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << mesh.nodeCount() << "\" NumberOfCells=\"" << mesh.cellCount()
      << "\">\n<PointData>\n";
  // One array of `count` components of f from component `first`, padded to 3 when 2.
  auto writeArray = [&](const NodalField& f, const std::string& name, int first, int count) {
    const int nc = static_cast<int>(f.components.size());
    out << "<DataArray type=\"Float64\" Name=\"" << name << "\" NumberOfComponents=\"" << (count == 2 ? 3 : count)
        << "\"";
    for (int k = 0; k < count; ++k) out << " ComponentName" << k << "=\"" << f.components[first + k] << "\"";
    out << " format=\"ascii\">\n";
    std::string text;
    for (int i = 0; i < mesh.nodeCount(); ++i) {
      for (int k = first; k < first + count; ++k) appendNumber(text, f.values[static_cast<std::size_t>(i) * nc + k]);
      if (count == 2) text += "0 ";
      text += '\n';
    }
    out << text << "</DataArray>\n";
  };
  for (const auto& f : fields) {
    const int nc = static_cast<int>(f.components.size());
    if (nc > 2 && f.components[0] == "DX" && f.components[1] == "DY" && f.components[2] != "DZ") {
      writeArray(f, f.name, 0, 2);
      for (int k = 2; k < nc; ++k) writeArray(f, f.name + "_" + f.components[k], k, 1);
    } else {
      writeArray(f, f.name, 0, nc);
    }
  }
  out << "</PointData>\n";
  if (!cellFields.empty()) {
    out << "<CellData>\n";
    for (const auto& f : cellFields) {
      const std::size_t nc = f.components.size();
      out << "<DataArray type=\"Float64\" Name=\"" << f.name << "_MEAN\" NumberOfComponents=\"" << nc << "\"";
      for (std::size_t k = 0; k < nc; ++k) out << " ComponentName" << k << "=\"" << f.components[k] << "\"";
      // Binary (base64), which holds the NaN of the cells outside the field exactly as it is.
      out << " format=\"binary\">\n";
      std::vector<double> mean(static_cast<std::size_t>(mesh.cellCount()) * nc, std::nan(""));
      for (std::size_t k = 0; k < f.cells.size(); ++k)
        for (std::size_t c = 0; c < nc; ++c) mean[static_cast<std::size_t>(f.cells[k]) * nc + c] = pointMean(f, k, c);
      out << base64Block(mean) << "\n</DataArray>\n";
    }
    out << "</CellData>\n";
  }
  out << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  std::string points;
  for (int i = 0; i < mesh.nodeCount(); ++i) {
    const auto x = mesh.node(i);
    for (int k = 0; k < 3; ++k) appendNumber(points, x[k]);
    points += '\n';
  }
  out << points;
  out << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (int c = 0; c < mesh.cellCount(); ++c) {
    const auto n = mesh.cellNodes(c);
    for (int k : fromAsterOrder(NodeConvention::Vtk, mesh.cellType(c), std::vector<int>(n.begin(), n.end())))
      out << k << " ";
    out << "\n";
  }
  out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  long offset = 0;
  for (int c = 0; c < mesh.cellCount(); ++c) out << (offset += mesh.cellNodes(c).size()) << "\n";
  out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (int c = 0; c < mesh.cellCount(); ++c) out << vtkType(mesh.cellType(c)) << "\n";
  out << "</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  file.close();
}

void writePvdCollection(const std::string& pvdPath, const std::vector<PvdEntry>& entries) {
  OutputFile file(pvdPath);
  std::ostream& out = file.stream();
  out << std::setprecision(16);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (const auto& e : entries)
    out << "<DataSet timestep=\"" << e.time << "\" part=\"0\" file=\"" << e.file << "\"/>\n";
  out << "</Collection>\n</VTKFile>\n";
  file.close();
}

void writePvd(const Mesh& mesh, const std::string& pvdPath, const std::vector<FieldInstant>& instants) {
  std::string stem = pvdPath;
  if (stem.size() > 4 && stem.substr(stem.size() - 4) == ".pvd") stem.resize(stem.size() - 4);
  std::vector<PvdEntry> entries;
  for (std::size_t k = 0; k < instants.size(); ++k) {
    const std::string vtu = stem + "_" + std::to_string(k) + ".vtu";
    writeVtu(mesh, vtu, instants[k].fields, instants[k].cellFields);
    entries.push_back({instants[k].time, baseName(vtu)});
  }
  writePvdCollection(pvdPath, entries);
}

}  // namespace aster::mesh
