// The nodes of a glTF 2.0 model that its scene draws, each after its parent: the roots (the
// default scene's nodes, else scene 0's, else every node that is no node's child) and their
// descendants, depth first. glTF requires the hierarchy to be disjoint strict trees; refused (the
// "what" part of a sentence, without the file): a node, child or root index that does not exist,
// a node that is a child of two nodes (or twice of one), a root that is also a child, a root
// listed twice, a default scene that does not exist. So each node is visited at most once (no
// cycle, no exponential re-visiting of shared subtrees from a small file), and the walk uses no
// recursion (a chain of 100,000 nodes cannot exhaust the stack). Internal to gltf_loader.cpp.
#pragma once

#include <expected>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace vem::scene {

struct NodeVisit {
  int node = 0;
  int parent = -1;  // -1 for a root
};

[[nodiscard]] std::expected<std::vector<NodeVisit>, std::string> nodesToDraw(
    const tinygltf::Model& model);

}  // namespace vem::scene
