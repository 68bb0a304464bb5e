// ShapeError: a particle shape cannot be used (mesh not closed, mis-oriented, degenerate,
// non-finite, bad generator parameters, bad scale factor). The message names the problem
// and, where there is one, the triangle / edge / vertex index, so the host layer can pass
// it on unchanged (e.g. prefixed with the shape name) in a LIGGGHTS error message.
#pragma once

#include <stdexcept>
#include <string>

namespace tri {

class ShapeError : public std::runtime_error {
public:
  explicit ShapeError(const std::string &message) : std::runtime_error(message) {}
};

} // namespace tri
