#pragma once
// A list of ids per item (a point's neighbours, the points near a brick),
// filled by the blocks of one ThreadPool::parallel_for and read by later
// passes: each block appends to its own vector, and each item keeps the run
// of it that holds its ids. The storage survives reset(), so a loop that
// refills the lists every step does not allocate.
#include <cstdint>
#include <span>
#include <vector>

#include "core/util/thread_pool.hpp"

namespace amls {

class IdLists {
 public:
  // Forgets the lists (keeping their storage) and makes room for `items`
  // runs filled by up to `blocks` blocks.
  void reset(std::size_t items, int blocks) {
    lists_.resize(static_cast<std::size_t>(blocks));
    for (OwnCacheLine<std::vector<std::uint32_t>>& list : lists_) list.value.clear();
    runs_.assign(items, {});
  }

  // Called by block `block` for item i: the ids it appends to the returned
  // vector until it calls finish(i, block) are i's.
  std::vector<std::uint32_t>& start(std::size_t i, int block) {
    std::vector<std::uint32_t>& list = lists_[static_cast<std::size_t>(block)].value;
    runs_[i] = {block, static_cast<std::uint32_t>(list.size()), static_cast<std::uint32_t>(list.size())};
    return list;
  }
  void finish(std::size_t i, int block) {
    runs_[i].end = static_cast<std::uint32_t>(lists_[static_cast<std::size_t>(block)].value.size());
  }

  std::span<const std::uint32_t> of(std::size_t i) const {
    const Run& r = runs_[i];
    return std::span(lists_[static_cast<std::size_t>(r.block)].value).subspan(r.begin, r.end - r.begin);
  }

 private:
  struct Run {
    int block = 0;
    std::uint32_t begin = 0;
    std::uint32_t end = 0;
  };
  std::vector<OwnCacheLine<std::vector<std::uint32_t>>> lists_;  // per block, appended to at the same time
  std::vector<Run> runs_;                                        // per item
};

}  // namespace amls
