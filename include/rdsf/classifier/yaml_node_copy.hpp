#pragma once
// Copies a cv::FileStorage node (map, sequence or scalar, recursively) into a storage being written: how a
// model file embeds another YAML document (the OpenCV backend's cv::ml::Boost) as a nested node, and how
// that node is turned back into a document of its own.
#include <string>

#include <opencv2/core.hpp>

namespace rdsf {

/// Writes `node` under `name` (empty inside a sequence) into `out`. Sequences of scalars are written in
/// flow style ([a, b, ...]); values keep their type (integer, real, text).
void copy_yaml_node(cv::FileStorage& out, const std::string& name, const cv::FileNode& node);

}  // namespace rdsf
