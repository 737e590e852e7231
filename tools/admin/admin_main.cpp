// ocean-admin: changes the scene one ocean-server runs, or prints the scene in force.
//   ocean-admin --server 127.0.0.1:7700 --token-file ./admin-token --wind-speed 18 --spectrum jonswap
//   ocean-admin --server 127.0.0.1:7700 --show
//   ocean-admin --server 127.0.0.1:7700 --token-file ./admin-token query --at 10,20 --at 30,-5
// Exit codes (admin_options.hpp): 0 ok, 2 usage/config, 3 refused by the server, 4 unreachable.
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <variant>
#include <vector>

#include "admin_link.hpp"
#include "admin_options.hpp"
#include "common/json_writer.hpp"
#include "message_builders.hpp"
#include "query_run.hpp"
#include "scene_json.hpp"

using namespace ocean;
using namespace ocean::admin;

namespace {

// SceneUpdates for later ticks follow the Welcome in one burst (PROTOCOL.md 5, step 2); a quiet
// spell this long after it means there are no more.
constexpr double kShowQuietS = 0.5;

int fail(int code, const std::string& what) {
  std::fprintf(stderr, "ocean-admin: %s\n", what.c_str());
  return code;
}

int refused(const protocol::Error& e) {
  return fail(kExitRefused, "refused by the server: " + std::string(protocol::to_string(e.code)) + ": " + e.text);
}

std::string update_json(const protocol::SceneUpdate& u) {
  common::JsonWriter json(common::JsonWriter::Style::compact);
  json.integer("effective_tick", u.effective_tick).integer("serial", u.serial).integer("request_id", u.request_id);
  if (u.vessels) {  // a vessel command's: how many tracks the fleet holds from its tick (the last two minutes')
    json.integer("tracks", static_cast<long long>(u.vessels->size()));
  }
  return json.raw("scene", scene_json(u.scene)).str();
}

int show(AdminLink& link, const protocol::Welcome& welcome) {
  std::vector<std::string> announced;
  std::string error;
  const auto quiet = [] {
    return AdminLink::Clock::now() + std::chrono::duration_cast<AdminLink::Clock::duration>(
                                         std::chrono::duration<double>(kShowQuietS));
  };
  while (true) {
    const auto m = link.receive(error, quiet());
    if (!m) {
      if (!link.timed_out()) return fail(kExitUnreachable, error);
      break;
    }
    if (const auto* u = std::get_if<protocol::SceneUpdate>(&*m)) announced.push_back(update_json(*u));
    if (std::holds_alternative<protocol::FrameData>(*m)) break;  // the stream began: the burst is over
    if (const auto* e = std::get_if<protocol::Error>(&*m)) return refused(*e);
  }
  std::string list = "[";
  for (const std::string& a : announced) list += (list.size() > 1 ? "," : "") + a;
  common::JsonWriter json(common::JsonWriter::Style::compact);
  json.integer("current_tick", welcome.current_tick).integer("serial", welcome.scene_serial);
  json.raw("scene", scene_json(welcome.scene)).raw("announced", list + "]");
  std::printf("%s\n", json.str().c_str());
  return kExitOk;
}

int change(AdminLink& link, const AdminOptions& o, const protocol::Welcome& welcome) {
  protocol::ParamChange request = o.change;
  // Random, so our SceneUpdate is told apart from another admin's running at the same time.
  std::random_device entropy;
  request.request_id = std::uniform_int_distribution<std::uint32_t>(1, UINT32_MAX)(entropy);
  std::string error;
  if (!link.send(protocol::encode(request), error)) return fail(kExitUnreachable, error);
  while (true) {
    const auto m = link.receive(error);
    if (!m) return fail(kExitUnreachable, error);
    if (const auto* e = std::get_if<protocol::Error>(&*m)) return refused(*e);
    if (const auto* b = std::get_if<protocol::Bye>(&*m))
      return fail(kExitUnreachable, "the server ended the session before answering: " + b->text);
    const auto* u = std::get_if<protocol::SceneUpdate>(&*m);
    if (!u || u->request_id != request.request_id) continue;  // frames, and scenes announced before ours
    common::JsonWriter json(common::JsonWriter::Style::compact);
    json.integer("effective_tick", u->effective_tick).integer("serial", u->serial);
    json.integer("request_id", u->request_id).integer("welcome_tick", welcome.current_tick);
    if (u->vessels) json.integer("tracks", static_cast<long long>(u->vessels->size()));
    std::printf("%s\n", json.raw("scene", scene_json(u->scene)).str().c_str());
    (void)link.send(protocol::encode(protocol::Bye{wire::ByeReason::client_quit, "ocean-admin done"}), error);
    return kExitOk;
  }
}

}  // namespace

int main(int argc, char** argv) {
  const AdminOptionsResult parsed = parse_admin_options({argv + 1, argv + argc}, std::getenv("OCEAN_ADMIN_TOKEN"));
  if (parsed.help) {
    std::printf("%s", parsed.error.c_str());
    return kExitOk;
  }
  if (!parsed.error.empty()) return fail(kExitUsage, parsed.error);
  const AdminOptions& o = parsed.options;

  // A repeated query runs for its queries' time, then the timeout as for one exchange.
  AdminLink link(o.timeout_s + (o.query ? (o.query_repeat - 1) / o.query_rate_hz : 0.0));
  std::string error;
  if (!link.connect(o.server, error)) return fail(kExitUnreachable, error);
  protocol::Hello hello;
  hello.transport = wire::Transport::tcp;  // frames it never decodes should not need a UDP proof
  hello.client_name = "ocean-admin";
  if (!link.send(protocol::encode(hello), error)) return fail(kExitUnreachable, error);
  const auto first = link.receive(error);
  if (!first) return fail(kExitUnreachable, error);
  if (const auto* e = std::get_if<protocol::Error>(&*first)) return refused(*e);
  const auto* welcome = std::get_if<protocol::Welcome>(&*first);
  if (!welcome) return fail(kExitUnreachable, "the server answered the Hello with something other than a Welcome");
  link.set_max_message_bytes(welcome->max_message_bytes);
  if (o.query) return run_query(link, o);
  return o.show ? show(link, *welcome) : change(link, o, *welcome);
}
