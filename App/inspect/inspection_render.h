// Headless inspection pictures: a shape is tessellated for inspection, coloured by a
// curvature quantity or striped by reflection lines / isophotes, and rasterized in
// software (orthographic, z-buffer, deferred per-pixel shading with the exact vertex
// normals interpolated, 2x2 supersampling), with face boundaries drawn and, for curvature,
// a legend with numbers. Per-pixel stripes from interpolated normals keep the stripes as
// smooth as the tessellation's normal bound allows. Used by `holefill render`, the Python
// API, demo-out/ and the benchmarks; the FreeCAD views use Coin3D overlays instead (Gui/).
#pragma once

#include <Eigen/Dense>
#include <TopoDS_Shape.hxx>
#include <map>
#include <string>

#include "inspect/color_scale.h"
#include "inspect/inspection_values.h"
#include "inspect/raster_image.h"
#include "inspect/shape_tessellation.h"

namespace holefill {

enum class RenderMode { Shaded, Curvature, Zebra };
RenderMode renderModeFromString(const std::string& s);  // shaded|curvature|zebra
std::string toString(RenderMode m);

// An orthographic view: direction into the scene and the up vector.
struct ViewDirection {
  Eigen::Vector3d view = Eigen::Vector3d(-1, 1, -1).normalized(), up = Eigen::Vector3d::UnitZ();
};
// iso (FreeCAD's isometric), top, bottom, front, back, left, right, or "dx,dy,dz" (view direction).
ViewDirection viewFromString(const std::string& s);

struct RenderOptions {
  RenderMode mode = RenderMode::Zebra;
  int width = 1024, height = 768;
  ViewDirection view;
  CurvatureQuantity quantity = CurvatureQuantity::Mean;
  Eigen::Vector3d curvatureDirection = Eigen::Vector3d::UnitX();  // for CurvatureQuantity::Direction
  ColorScaleOptions scale;
  StripeOptions stripes;
  bool edges = true;     // draw the B-rep edges
  bool legend = true;    // colour bar with numbers (curvature) and a caption line
  int supersample = 2;   // per axis
  TessellationOptions tessellation;
};

struct RenderResult {
  RasterImage image;
  ColorScale scale;                       // curvature mode: the range the colours span
  double valueMin = 0, valueMax = 0;      // curvature mode: finite extremes of the values
  double maxInteriorNormalAngle = 0, maxBoundaryNormalAngle = 0;
  Eigen::Index vertices = 0, triangles = 0;
  int refinementPasses = 0;
  std::vector<std::string> warnings;
  double tessellationSeconds = 0, renderSeconds = 0;
};

RenderResult renderInspection(const TopoDS_Shape& shape, const RenderOptions& options = {});
// Renders an already tessellated mesh (curvature values and scale computed here).
RenderResult renderInspection(const InspectionMesh& mesh, const RenderOptions& options);

// The options as the doors spell them (CLI --key value, Python keyword=value), parsed in one
// place so both give the same errors: mode, quantity, direction "x,y,z", size "WxH", view,
// stripes N, stripe-width W, stripe-angle DEG, stripe-mode reflection|isophote,
// isophote-direction "x,y,z", scale-percentile "LO,HI", scale-range "LO,HI",
// symmetric auto|yes|no, faces "1,2,..", normal-angle DEG, edges 0|1, legend 0|1, supersample N.
RenderOptions parseRenderOptions(const std::map<std::string, std::string>& options);

// Report of a render (sizes, scale, extremes, reached normal bound, timings, warnings) as JSON.
std::string toJson(const RenderResult& r, const RenderOptions& o);

}  // namespace holefill
