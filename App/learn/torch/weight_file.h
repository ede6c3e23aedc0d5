// The weight files of the learned models (UVTran, BIDGCN): a torch archive holding a format tag
// (bumped when a network changes incompatibly), the network's config record, a model card and
// the parameters. Loading checks all of them and every parameter's shape and finiteness, and
// says what is wrong; a file that fails leaves nothing half-loaded for the caller. Writing goes
// through a temporary file and a rename. Header-only: included by the torch TUs of the models.
#pragma once

#include <torch/torch.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "geometry/error.h"

namespace holefill::learn {

inline void saveWeights(torch::nn::Module& net, const torch::Tensor& config, int64_t format, const std::string& card,
                        const std::string& path, const std::string& model) {
  torch::serialize::OutputArchive a;
  a.write("format", torch::tensor({format}));
  a.write("config", config);
  std::vector<int64_t> bytes(card.begin(), card.end());
  a.write("card", torch::tensor(bytes.empty() ? std::vector<int64_t>{0} : bytes));
  torch::serialize::OutputArchive params;
  net.save(params);
  a.write("net", params);
  const std::string tmp = path + ".tmp";
  a.save_to(tmp);
  if (std::rename(tmp.c_str(), path.c_str()) != 0) throw Error("cannot write " + model + " weights to " + path);
}

// Opens the archive and checks its format; returns the config record.
inline torch::Tensor openWeights(torch::serialize::InputArchive& a, const std::string& path, int64_t format, const std::string& model) {
  if (!std::ifstream(path, std::ios::binary)) throw Error(model + " weights not found: " + path);
  try {
    a.load_from(path);
  } catch (const c10::Error&) {
    throw Error(model + " weights " + path + " are not a readable torch archive (truncated or corrupt)");
  }
  torch::Tensor tag, config;
  try {
    a.read("format", tag);
    a.read("config", config);
  } catch (const c10::Error&) {
    throw Error(model + " weights " + path + " have no format/config record: not a HoleFill " + model + " file");
  }
  if (tag.numel() != 1 || tag.item<int64_t>() != format)
    throw Error(model + " weights " + path + " are of format " + std::to_string(tag.numel() ? tag.item<int64_t>() : 0) +
                ", this build reads " + std::to_string(format) + ": retrain or use matching weights");
  return config;
}

// Loads the parameters into `net` (built from the config record) and checks them.
inline void loadWeights(torch::serialize::InputArchive& a, torch::nn::Module& net, const std::string& path, const std::string& model) {
  std::map<std::string, std::vector<int64_t>> shapes;
  for (const auto& p : net.named_parameters()) shapes[p.key()] = p.value().sizes().vec();
  for (const auto& p : net.named_buffers()) shapes[p.key()] = p.value().sizes().vec();
  try {
    torch::serialize::InputArchive params;
    a.read("net", params);
    net.load(params);
  } catch (const c10::Error& e) {
    throw Error(model + " weights " + path + " do not match the network: " + std::string(e.what_without_backtrace()).substr(0, 200));
  }
  for (const auto& p : net.named_parameters()) {
    if (p.value().sizes().vec() != shapes[p.key()]) throw Error(model + " weights " + path + ": parameter " + p.key() + " has the wrong shape");
    if (!torch::isfinite(p.value()).all().item<bool>())
      throw Error(model + " weights " + path + ": parameter " + p.key() + " holds NaN or infinity");
  }
  net.eval();
}

}  // namespace holefill::learn
