#include "stream_listen_options.hpp"

#include "option_values.hpp"
#include "stream_transports.hpp"

#include <array>
#include <iterator>
#include <string>
#include <string_view>
#include <utility>

namespace ocean::server {
namespace {

// The optional stream transports' listen options, one per row of kStreamTransports that names one
// (the primary's, --listen, is an ordinary option). The rows' text is copied at compile time: the
// rows also name their links' factories, link code that this library must never reference at run
// time (its fuzzer links it alone).
struct ListenRow {
  std::string_view name, option, help;
};
consteval std::size_t listen_row_count() {
  std::size_t count = 0;
  for (const StreamTransport& row : kStreamTransports) count += !row.option.empty();
  return count;
}
consteval std::array<ListenRow, listen_row_count()> listen_rows() {
  std::array<ListenRow, listen_row_count()> rows{};
  std::size_t i = 0;
  for (const StreamTransport& row : kStreamTransports)
    if (!row.option.empty()) rows[i++] = {row.name, row.option, row.help};
  return rows;
}
constexpr auto kListenRows = listen_rows();

template <std::size_t I>
std::string apply_stream_listen(ServerConfig& c, std::string_view v) {
  return apply_address(c.stream_listen, kListenRows[I].name, v);
}
template <std::size_t I>
std::string show_stream_listen(const ServerConfig& c) {
  const ListenAddress* address = c.stream_address(kListenRows[I].name);
  return address ? address->to_string() : std::string("off");
}
template <std::size_t... I>
constexpr std::array<ConfigOption, sizeof...(I)> listen_options(std::index_sequence<I...>) {
  return {ConfigOption{kListenRows[I].option, "ADDR:PORT|off", kListenRows[I].help, ValueKind::text, false,
                       apply_stream_listen<I>, show_stream_listen<I>}...};
}
constexpr auto kListenOptions = listen_options(std::make_index_sequence<kListenRows.size()>());

}  // namespace

std::span<const ConfigOption> stream_listen_options() { return kListenOptions; }

}  // namespace ocean::server
