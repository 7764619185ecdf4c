// crspline command line: rotation and pose curve files (issue 28).
//
// A curve file with "rotations" is a rotation curve (or, with "points" too, a
// pose curve: positions and rotations on one grid). The rotations come in
// one of five forms, each an object with one key:
//   {"quaternions": [[w, x, y, z], ...]}
//   {"rotation_vectors": [[x, y, z], ...], "degrees": false}
//   {"axis_angle": [[ax, ay, az, angle], ...], "degrees": false}
//   {"euler": {"convention": "xyz", "angles": [[a, b, c], ...], "degrees": false}}
//   {"matrices": [[[r00, r01, r02], [r10, r11, r12], [r20, r21, r22]], ...]}
// Beside them: "kind" (catmull_rom, kochanek_bartels, slerp, barry_goldman,
// squad, c2), "alpha" or "grid", "closed", "start"/"end", "tcb",
// "keep_signs", "strict", "frame" (of the rates written), "knots" (the
// grid in the JSON output), and what eval
// ("t", "derivatives") and sample ("count", "spacing", "derivatives") read.
// Every shape error names the field's path and index, as the point files do
// ("rotations.euler.angles[2][1]: expected a finite number, got \"a\"").
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <crspline/rotation/c2.hpp>
#include <crspline/rotation/catmull_rom.hpp>
#include <crspline/rotation/pose.hpp>
#include <crspline/rotation/quaternion.hpp>

#include "json_parser.hpp"

namespace crspline::cli {

/// True when the document is a rotation or pose curve file (it has "rotations").
bool is_rotation_document(const document& doc);

/// A rotation or pose curve file, read and checked for shape; the core
/// validates the values (alpha, grid, unit keys) when the curve is built.
struct rotation_file {
    std::vector<rotation::quaternion<double>> keys;
    std::string keys_path;                          ///< "rotations.quaternions", for messages about key i
    std::vector<vec<3, double>> positions;          ///< a pose curve's points (empty: rotations only)
    std::string kind = "catmull_rom";               ///< as written (pose: "c2" by default)
    std::optional<double> alpha;
    std::optional<std::vector<double>> grid;
    bool closed = false, keep_signs = false, strict = false;
    rotation::rotation_end<double> start_cr{}, end_cr{};  ///< catmull_rom / kochanek_bartels ends
    rotation::c2_end<double> start_c2{}, end_c2{};        ///< c2 ends
    std::vector<rotation::tcb<double>> tcb;
    rotation::frame out_frame = rotation::frame::world;   ///< frame of the rates written
    bool knots = false;                                   ///< the JSON output includes the knot grid
    // eval
    std::vector<double> t;
    std::string t_name = "t";
    std::vector<int> derivatives{0};
    // sample
    std::size_t count = 0;
    std::string spacing = "t";  ///< t | angle | arc_length (pose)
    bool pose() const noexcept { return !positions.empty(); }
};

/// Reads a rotation file for `command` ("eval" or "sample"); errors are
/// input_error naming the field (and the file, for a named file).
rotation_file parse_rotation_file(const document& doc, const std::string& command);

}  // namespace crspline::cli
