#include <doctest/doctest.h>

#include <chrono>
#include <future>
#include <thread>

#include "app/editor/command_queue.hpp"

using namespace amls;
using namespace amls::editor;

namespace {

command::MoveHandles move_to(double x) { return command::MoveHandles{{Vec<3>(x, 0.0, 0.0)}, {}}; }

double moved_x(const QueuedCommand& q) { return std::get<command::MoveHandles>(q.command).positions.at(0).x(); }

}  // namespace

TEST_CASE("queued handle moves coalesce: the newest position wins and takes the newest sequence number") {
  CommandQueue queue;
  queue.push(command::BeginDrag{});
  queue.push(move_to(1.0));
  queue.push(move_to(2.0));
  const std::uint64_t last = queue.push(move_to(3.0));
  CHECK(queue.size() == 2);
  CHECK(std::holds_alternative<command::BeginDrag>(queue.pop()->command));
  const QueuedCommand move = *queue.pop();
  CHECK(moved_x(move) == 3.0);
  CHECK(move.sequence == last);
}

TEST_CASE("coalesced moves keep the newest regions' motions too, not only the handles' places") {
  CommandQueue queue;
  auto move_region_to = [](double x) {
    command::RegionMove region;
    region.translation = Vec<3>(x, 0.0, 0.0);
    return command::MoveHandles{{Vec<3>::Zero()}, {region}};
  };
  queue.push(move_region_to(0.1));
  queue.push(move_region_to(0.2));
  queue.push(move_region_to(0.3));
  REQUIRE(queue.size() == 1);
  const auto move = std::get<command::MoveHandles>(queue.pop()->command);
  REQUIRE(move.regions.size() == 1);
  CHECK(move.regions[0].translation.x() == 0.3);
}

TEST_CASE("moves separated by another command are kept apart, in order") {
  CommandQueue queue;
  queue.push(move_to(1.0));
  queue.push(command::AddHandle{Vec<3>::Zero()});
  queue.push(move_to(2.0));
  REQUIRE(queue.size() == 3);
  CHECK(moved_x(*queue.pop()) == 1.0);
  CHECK(std::holds_alternative<command::AddHandle>(queue.pop()->command));
  CHECK(moved_x(*queue.pop()) == 2.0);
}

TEST_CASE("a load or a parameter change moves the cancel epoch on - a handle edit does not") {
  CommandQueue queue;
  const std::uint64_t start = queue.cancel_epoch();
  queue.push(command::AddHandle{Vec<3>::Zero()});
  queue.push(move_to(1.0));
  queue.push(command::Export{"x.ply"});
  CHECK(queue.cancel_epoch() == start);
  queue.push(command::SetGrid{0.01, 3.0});
  CHECK(queue.cancel_epoch() == start + 1);
  queue.push(command::LoadFile{"x.ply"});
  CHECK(queue.cancel_epoch() == start + 2);
}

TEST_CASE("a popped command carries the epoch it was popped in, so later cancels are seen") {
  CommandQueue queue;
  queue.push(move_to(1.0));
  const QueuedCommand running = *queue.pop();
  CHECK(running.epoch == queue.cancel_epoch());
  queue.push(command::SetVariant{Variant::interpolated});
  CHECK(running.epoch != queue.cancel_epoch());
  CHECK(queue.pop()->epoch == queue.cancel_epoch());
}

TEST_CASE("a running load is stopped by another load or Esc, not by a setting, undo or reset queued behind it") {
  CommandQueue queue;
  queue.push(command::LoadFile{"scan.xyz"});
  const QueuedCommand loading = *queue.pop();
  queue.push(command::SetVariant{Variant::interpolated});
  queue.push(command::SetGrid{0.01, 3.0});
  queue.push(command::Undo{});
  queue.push(command::Reset{});
  CHECK(loading.epoch == queue.cancel_epoch());
  queue.push(command::CancelDrag{});
  CHECK(loading.epoch != queue.cancel_epoch());

  queue.push(command::LoadFile{"other.xyz"});
  while (!std::holds_alternative<command::LoadFile>(queue.pop()->command)) {
  }
  const std::uint64_t second = queue.cancel_epoch();
  queue.push(command::LoadShape{});
  CHECK(queue.cancel_epoch() == second + 1);
  // Once something other than a load runs, a setting stops it again.
  queue.pop();
  queue.push(move_to(1.0));
  queue.pop();
  queue.push(command::SetVariant{Variant::exact});
  CHECK(queue.cancel_epoch() == second + 2);
}

TEST_CASE("a load, Esc or undo drops the moves still queued - a parameter change keeps them") {
  CommandQueue queue;
  queue.push(move_to(1.0));
  queue.push(command::SetDeformation{MlsKind::affine, 1.0});
  CHECK(queue.size() == 2);
  queue.push(command::CancelDrag{});
  CHECK(queue.size() == 2);  // the move went, the cancel came
  CHECK(std::holds_alternative<command::SetDeformation>(queue.pop()->command));
  CHECK(std::holds_alternative<command::CancelDrag>(queue.pop()->command));
  queue.push(move_to(2.0));
  queue.push(command::Undo{});
  CHECK(queue.size() == 1);
}

TEST_CASE("close wakes a waiting pop, drops what is queued and refuses new commands") {
  CommandQueue queue;
  auto waiting = std::async(std::launch::async, [&] { return queue.pop(); });
  CHECK(waiting.wait_for(std::chrono::milliseconds(50)) == std::future_status::timeout);
  queue.close();
  REQUIRE(waiting.wait_for(std::chrono::seconds(10)) == std::future_status::ready);
  CHECK(!waiting.get().has_value());
  CHECK(queue.push(move_to(1.0)) == 0);
  CHECK(queue.size() == 0);
  CHECK(!queue.pop().has_value());
}

TEST_CASE("commands pushed from another thread arrive whole and in order") {
  CommandQueue queue;
  constexpr int kCount = 2000;
  std::thread producer([&] {
    for (int i = 0; i < kCount; ++i) queue.push(command::RemoveHandle{static_cast<std::size_t>(i)});
  });
  for (int i = 0; i < kCount; ++i) CHECK(std::get<command::RemoveHandle>(queue.pop()->command).index == std::size_t(i));
  producer.join();
}
