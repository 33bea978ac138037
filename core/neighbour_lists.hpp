#pragma once
// Every point's neighbours, gathered once by one parallel pass and read by
// later passes: per point, a run of the list its thread block filled.
#include <cstdint>
#include <span>
#include <vector>

namespace amls {

class NeighbourLists {
 public:
  // Forgets the lists (keeping their storage) and makes room for `points`
  // runs filled by up to `blocks` blocks.
  void reset(std::size_t points, int blocks) {
    lists_.resize(static_cast<std::size_t>(blocks));
    for (std::vector<std::uint32_t>& list : lists_) list.clear();
    runs_.assign(points, {});
  }

  // Called by block `block` for point i: the ids it appends to the returned
  // list until it calls end_point(i, block) are i's neighbours.
  std::vector<std::uint32_t>& begin_point(std::size_t i, int block) {
    std::vector<std::uint32_t>& list = lists_[static_cast<std::size_t>(block)];
    runs_[i] = {block, static_cast<std::uint32_t>(list.size()), static_cast<std::uint32_t>(list.size())};
    return list;
  }
  void end_point(std::size_t i, int block) {
    runs_[i].end = static_cast<std::uint32_t>(lists_[static_cast<std::size_t>(block)].size());
  }

  std::size_t points() const { return runs_.size(); }
  std::span<const std::uint32_t> of(std::size_t i) const {
    const Run& r = runs_[i];
    return std::span(lists_[static_cast<std::size_t>(r.block)]).subspan(r.begin, r.end - r.begin);
  }

 private:
  struct Run {
    int block = 0;
    std::uint32_t begin = 0;
    std::uint32_t end = 0;
  };
  std::vector<std::vector<std::uint32_t>> lists_;  // per block
  std::vector<Run> runs_;                          // per point
};

}  // namespace amls
