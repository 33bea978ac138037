#pragma once
// std::visit with one lambda per alternative: std::visit(Overloaded{[](const A&) {...}, [](const B&) {...}}, v).

namespace amls::editor {

template <typename... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <typename... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

}  // namespace amls::editor
