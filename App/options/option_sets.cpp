#include "options/option_sets.h"

#include "geometry/error.h"
#include "options/gnurbs_build_schema.h"
#include "options/hole_fill_schema.h"
#include "options/labeled_fit_schema.h"
#include "options/mesh_fill_schema.h"
#include "options/point_cloud_fit_schema.h"

namespace holefill {

std::vector<std::string> optionSetNames() { return {"fill", "labeled_fit", "mesh_fill", "gnurbs", "point_fit"}; }

std::string optionSetJson(const std::string& set) { return optionSet(set).toJson(); }

OptionList optionSet(const std::string& set) {
  if (set == "fill") return optionList(holeFillSchema());
  if (set == "labeled_fit") return optionList(labeledFitSchema());
  if (set == "mesh_fill") return optionList(meshFillSchema());
  if (set == "gnurbs") return optionList(gnurbsBuildSchema());
  if (set == "point_fit") return optionList(pointCloudFitSchema());
  std::string list;
  for (const auto& n : optionSetNames()) list += (list.empty() ? "" : ", ") + n;
  throw Error("unknown option set '" + set + "': the sets are " + list);
}

}  // namespace holefill
