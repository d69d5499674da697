// The result a mesh reader gives up with, shared by the OFF/OBJ
// (mesh_io.cpp), PLY and STL readers.
#pragma once

#include <string>

#include "mesh_types.h"

namespace subdivlab::detail {

/// A parse_error "line N: what" (`what` alone when `line` is 0: binary data
/// names its byte offset itself).
inline Result<Mesh_buffers> parse_failure(int line, const std::string& what) {
  Result<Mesh_buffers> r;
  r.status = Status::error(
      Status_code::parse_error,
      (line > 0 ? "line " + std::to_string(line) + ": " : "") + what, line);
  return r;
}

}  // namespace subdivlab::detail
