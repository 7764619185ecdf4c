// crspline command line: inputs that hold many curves. A font, a map or a
// set of GPS tracks is thousands of curves; one process reads them all and
// gives one result per curve, in input order (docs/cli.md, "MANY CURVES").
//
//   a JSON list of curve objects     [{"points": ..., "id": "a"}, {...}]
//   GeoJSON                          LineString, Polygon (each ring a closed
//                                    curve), their Multi* forms, Feature,
//                                    FeatureCollection (properties carried
//                                    to the output), GeometryCollection
//   SVG path data                    every subpath of every <path d="...">
//                                    (or bare path data); Z closes a subpath
//   CSV                              (csv_input.hpp) blank-line-separated
//                                    blocks, or a curve-id column
//
// Each curve becomes a document with its id (for messages and the output)
// and the location of its points (JSON path, or line in the text).
#pragma once

#include <optional>
#include <vector>

#include "json_parser.hpp"

namespace crspline::cli {

/// The curves of a parsed JSON input when it is a list of curve objects or a
/// GeoJSON object; nullopt for one curve object.
std::optional<std::vector<document>> json_curves(const document& parsed, const input_text& in);

/// The curves of SVG path data: the subpaths of every <path d="..."> of an
/// SVG file, or of bare path data. A subpath's points are the end points of
/// its commands (control points of C, S, Q, T and arcs are not on the
/// curve); Z makes it a closed curve (its repeated first point dropped).
std::vector<document> svg_curves(const input_text& in);

/// Whether the text looks like SVG (an XML document or bare path data).
bool looks_like_svg(const std::string& text);

}  // namespace crspline::cli
