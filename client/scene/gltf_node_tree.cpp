#include "client/scene/gltf_node_tree.h"

#include <fmt/format.h>
#include <tiny_gltf.h>
#include <algorithm>
#include <cstddef>
#include <ranges>

namespace vem::scene {
namespace {

constexpr int kNoParent = -1;

bool exists(int index, std::size_t count) {
  return index >= 0 && static_cast<std::size_t>(index) < count;
}

// Each node's parent, or the first node with two parents (or a child that does not exist).
std::expected<std::vector<int>, std::string> parents(const tinygltf::Model& model) {
  const std::size_t count = model.nodes.size();
  std::vector<int> parentOf(count, kNoParent);
  for (std::size_t n = 0; n < count; ++n) {
    for (const int child : model.nodes[n].children) {
      if (!exists(child, count)) {
        return std::unexpected(fmt::format(
            "node {} has the child {}, which does not exist ({} nodes)", n, child, count));
      }
      int& parent = parentOf[static_cast<std::size_t>(child)];
      if (parent == static_cast<int>(n)) {
        return std::unexpected(fmt::format(
            "node {} is listed twice among node {}'s children, where a tree was expected", child,
            n));
      }
      if (parent != kNoParent) {
        return std::unexpected(fmt::format(
            "node {} is a child of node {} and of node {}, where a tree (one parent) was expected",
            child, parent, n));
      }
      parent = static_cast<int>(n);
    }
  }
  return parentOf;
}

std::expected<std::vector<int>, std::string> roots(const tinygltf::Model& model,
                                                   const std::vector<int>& parentOf) {
  const auto& scenes = model.scenes;
  if (model.defaultScene >= static_cast<int>(scenes.size())) {
    return std::unexpected(fmt::format("the default scene {} does not exist ({} scenes)",
                                       model.defaultScene, scenes.size()));
  }
  std::vector<int> out;
  if (scenes.empty()) {
    for (std::size_t n = 0; n < parentOf.size(); ++n) {
      if (parentOf[n] == kNoParent) {
        out.push_back(static_cast<int>(n));
      }
    }
    return out;
  }
  out = scenes[static_cast<std::size_t>(std::max(model.defaultScene, 0))].nodes;
  std::vector<bool> listed(parentOf.size(), false);
  for (const int root : out) {
    if (!exists(root, parentOf.size())) {
      return std::unexpected(
          fmt::format("node {} does not exist ({} nodes)", root, parentOf.size()));
    }
    const auto r = static_cast<std::size_t>(root);
    if (parentOf[r] != kNoParent) {
      return std::unexpected(fmt::format(
          "node {} is a root of the scene and a child of node {}, where a tree was expected", root,
          parentOf[r]));
    }
    if (listed[r]) {
      return std::unexpected(fmt::format("node {} is listed twice among the scene's roots", root));
    }
    listed[r] = true;
  }
  return out;
}

}  // namespace

std::expected<std::vector<NodeVisit>, std::string> nodesToDraw(const tinygltf::Model& model) {
  const auto parentOf = parents(model);
  if (!parentOf) {
    return std::unexpected(parentOf.error());
  }
  const auto rootNodes = roots(model, *parentOf);
  if (!rootNodes) {
    return std::unexpected(rootNodes.error());
  }
  std::vector<NodeVisit> visits;
  std::vector<NodeVisit> pending;  // a stack, so that the walk is depth first
  for (const int root : std::views::reverse(*rootNodes)) {
    pending.push_back({root, kNoParent});
  }
  while (!pending.empty()) {
    const NodeVisit visit = pending.back();
    pending.pop_back();
    visits.push_back(visit);
    const auto& children = model.nodes[static_cast<std::size_t>(visit.node)].children;
    for (const int child : std::views::reverse(children)) {
      pending.push_back({child, visit.node});
    }
  }
  return visits;
}

}  // namespace vem::scene
