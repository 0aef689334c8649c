// What a translation knows statically of a value, to choose Lua's operator
// (a + b, x % y, L[i]) where Python's depends on the type, or a run-time helper.
#pragma once

namespace aster::comm {

// What is statically known of a value. Index: an integer known to be >= 0.
enum class Ty { Bottom, Unknown, Index, Int, Float, Num, Str, Bool, List, Dict, None, Func };

inline bool isNum(Ty t) { return t == Ty::Index || t == Ty::Int || t == Ty::Float || t == Ty::Num; }
inline bool isInt(Ty t) { return t == Ty::Index || t == Ty::Int; }
inline bool isScalar(Ty t) { return isNum(t) || t == Ty::Str || t == Ty::Bool || t == Ty::None; }

inline Ty join(Ty a, Ty b) {
  if (a == Ty::Bottom) return b;
  if (b == Ty::Bottom || a == b) return a;
  if (isInt(a) && isInt(b)) return Ty::Int;
  if (isNum(a) && isNum(b)) return Ty::Num;
  return Ty::Unknown;
}
inline Ty numeric(Ty a, Ty b) {  // + - * on numbers
  if (a == Ty::Index && b == Ty::Index) return Ty::Index;
  if (isInt(a) && isInt(b)) return Ty::Int;
  if (a == Ty::Float || b == Ty::Float) return Ty::Float;
  return Ty::Num;
}

}  // namespace aster::comm
