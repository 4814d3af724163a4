// Checks of a surface file's structure before CGAL reads it. CGAL's readers size their arrays from
// what the file announces (an OFF header's counts, a face's vertex count, a PLY list's length) and
// convert numbers to indices without range checks: a file that announces 1e9 faces, or a face line
// "-1 0 1 2", would allocate gigabytes or convert out of range before any check of ours could run.
#pragma once

#include <string>

#include "kinestat/core/status.hpp"

namespace kinestat::fea {

// kInvalidInput naming the file and the record when:
// - OFF: the header is not a plain ASCII "OFF" (binary, colour, normal or texture variants are not
//   read), its counts need more bytes than the file has, or a face line's vertex count or indices
//   are not integers that the line and the vertex count allow (records one per line, as CGAL reads);
// - PLY: an element count exceeds the file's size, a property comes before any element, or a list's
//   length type is wider than 16 bits;
// - binary STL: the triangle count needs more bytes than the file has.
// OBJ and ASCII STL carry no counts. Anything else is left to CGAL's reader.
Status check_surface_file_structure(const std::string& path);

}  // namespace kinestat::fea
