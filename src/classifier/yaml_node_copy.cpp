#include "rdsf/classifier/yaml_node_copy.hpp"

namespace rdsf {

void copy_yaml_node(cv::FileStorage& out, const std::string& name, const cv::FileNode& node) {
  if (node.isMap() || node.isSeq()) {
    int flags = node.isMap() ? cv::FileNode::MAP : cv::FileNode::SEQ;
    if (node.isSeq()) {  // sequences of numbers and text stay on few lines, as OpenCV writes them
      bool scalars = true;
      for (auto it = node.begin(); it != node.end() && scalars; ++it) scalars = !(*it).isMap() && !(*it).isSeq();
      if (scalars) flags |= cv::FileNode::FLOW;
    }
    out.startWriteStruct(name, flags);
    for (auto it = node.begin(); it != node.end(); ++it) {
      const cv::FileNode child = *it;
      copy_yaml_node(out, node.isMap() ? child.name() : std::string(), child);
    }
    out.endWriteStruct();
  } else if (node.isInt()) {
    cv::write(out, name, static_cast<int>(node));
  } else if (node.isReal()) {
    cv::write(out, name, static_cast<double>(node));
  } else if (node.isString()) {
    cv::write(out, name, static_cast<std::string>(node));
  }
  // none/empty nodes are left out
}

}  // namespace rdsf
