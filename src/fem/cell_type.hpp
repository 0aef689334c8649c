// The reference cells of the program and a compile-time dispatch on them.
#pragma once
#include <string>
#include <type_traits>

#include "core/error.hpp"

namespace aster::fem {

// code_aster's names and node orderings (see shape_functions.hpp).
enum class CellType { SEG2, SEG3, TRIA3, TRIA6, QUAD4, QUAD8, QUAD9 };

inline const char* cellName(CellType t) {
  switch (t) {
    case CellType::SEG2: return "SEG2";
    case CellType::SEG3: return "SEG3";
    case CellType::TRIA3: return "TRIA3";
    case CellType::TRIA6: return "TRIA6";
    case CellType::QUAD4: return "QUAD4";
    case CellType::QUAD8: return "QUAD8";
    case CellType::QUAD9: return "QUAD9";
  }
  return "?";
}

constexpr int cellNodeCount(CellType t) {
  switch (t) {
    case CellType::SEG2: return 2;
    case CellType::SEG3: return 3;
    case CellType::TRIA3: return 3;
    case CellType::TRIA6: return 6;
    case CellType::QUAD4: return 4;
    case CellType::QUAD8: return 8;
    case CellType::QUAD9: return 9;
  }
  return 0;
}

constexpr int cellDimension(CellType t) {
  return (t == CellType::SEG2 || t == CellType::SEG3) ? 1 : 2;
}

template <CellType T>
using CellTag = std::integral_constant<CellType, T>;

// Calls f(CellTag<T>{}) for a surface (2D) cell type known only at run time.
template <class F>
decltype(auto) dispatchSurface(CellType t, F&& f) {
  switch (t) {
    case CellType::TRIA3: return f(CellTag<CellType::TRIA3>{});
    case CellType::TRIA6: return f(CellTag<CellType::TRIA6>{});
    case CellType::QUAD4: return f(CellTag<CellType::QUAD4>{});
    case CellType::QUAD8: return f(CellTag<CellType::QUAD8>{});
    case CellType::QUAD9: return f(CellTag<CellType::QUAD9>{});
    default: break;
  }
  throw Error(std::string("expected a surface cell (TRIA3, TRIA6, QUAD4, QUAD8, QUAD9), got ") + cellName(t));
}

// Calls f(CellTag<T>{}) for an edge (1D) cell type known only at run time.
template <class F>
decltype(auto) dispatchEdge(CellType t, F&& f) {
  switch (t) {
    case CellType::SEG2: return f(CellTag<CellType::SEG2>{});
    case CellType::SEG3: return f(CellTag<CellType::SEG3>{});
    default: break;
  }
  throw Error(std::string("expected an edge cell (SEG2, SEG3), got ") + cellName(t));
}

}  // namespace aster::fem
