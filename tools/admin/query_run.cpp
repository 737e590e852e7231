#include "query_run.hpp"

#include <algorithm>
#include <cstdio>
#include <random>
#include <thread>

#include "common/json_writer.hpp"
#include "message_builders.hpp"

namespace ocean::admin {
namespace {

int fail(int code, const std::string& what) {
  std::fprintf(stderr, "ocean-admin: %s\n", what.c_str());
  return code;
}

std::string answer_json(const protocol::HeightQuery& q, const protocol::HeightAnswer& a) {
  std::string points = "[";
  for (std::size_t i = 0; i < a.samples.size() && i < q.points.size(); ++i) {
    const wire::SurfaceSample& s = a.samples[i];
    common::JsonWriter p(common::JsonWriter::Style::compact);
    p.number("x_m", q.points[i].x_m(), 9).number("z_m", q.points[i].z_m(), 9).number("height_m", s.height_m(), 9);
    char normal[96];  // as number() writes each: %.7g, a float's digits
    std::snprintf(normal, sizeof normal, "[%.7g,%.7g,%.7g]", s.normal_x(), s.normal_y(), s.normal_z());
    p.raw("normal", normal);
    p.number("vertical_velocity_mps", s.vertical_velocity_mps(), 6);
    points += (i ? "," : "") + p.str();
  }
  common::JsonWriter json(common::JsonWriter::Style::compact);
  json.integer("tick", a.tick).integer("profile_id", a.profile_id).integer("request_id", a.request_id);
  return json.raw("points", points + "]").str();
}

// The answer to `request_id`, skipping frames and scenes; nullopt after an Error (told) or a loss.
std::optional<protocol::HeightAnswer> await_answer(AdminLink& link, std::uint32_t request_id, int& code) {
  std::string error;
  while (true) {
    const auto m = link.receive(error);
    if (!m) {
      code = fail(kExitUnreachable, error);
      return std::nullopt;
    }
    if (const auto* e = std::get_if<protocol::Error>(&*m)) {
      code = fail(kExitRefused, "refused by the server: " + std::string(protocol::to_string(e->code)) + ": " + e->text);
      return std::nullopt;
    }
    if (const auto* b = std::get_if<protocol::Bye>(&*m)) {
      code = fail(kExitUnreachable, "the server ended the session before answering: " + b->text);
      return std::nullopt;
    }
    if (const auto* a = std::get_if<protocol::HeightAnswer>(&*m); a && a->request_id == request_id) return *a;
  }
}

}  // namespace

int run_query(AdminLink& link, const AdminOptions& o) {
  protocol::HeightQuery query = *o.query;
  std::random_device entropy;
  std::uint32_t request_id = std::uniform_int_distribution<std::uint32_t>(1, UINT32_MAX / 2)(entropy);
  std::vector<double> latency_ms;
  std::optional<protocol::HeightAnswer> last;
  const auto period = std::chrono::duration_cast<AdminLink::Clock::duration>(std::chrono::duration<double>(1.0 / o.query_rate_hz));
  auto next = AdminLink::Clock::now();
  std::string error;
  int code = kExitOk;
  for (int i = 0; i < o.query_repeat; ++i) {
    std::this_thread::sleep_until(next);
    next += period;
    query.request_id = ++request_id;
    const auto sent = AdminLink::Clock::now();
    if (!link.send(protocol::encode(query), error)) return fail(kExitUnreachable, error);
    last = await_answer(link, query.request_id, code);
    if (!last) return code;
    latency_ms.push_back(std::chrono::duration<double, std::milli>(AdminLink::Clock::now() - sent).count());
  }
  (void)link.send(protocol::encode(protocol::Bye{wire::ByeReason::client_quit, "ocean-admin done"}), error);
  if (o.query_repeat == 1) {
    std::printf("%s\n", answer_json(query, *last).c_str());
    return kExitOk;
  }
  std::sort(latency_ms.begin(), latency_ms.end());
  const auto at = [&](double q) { return latency_ms[static_cast<std::size_t>(q * (latency_ms.size() - 1))]; };
  common::JsonWriter json(common::JsonWriter::Style::compact);
  json.integer("queries", static_cast<long long>(latency_ms.size())).integer("points", static_cast<long long>(query.points.size()));
  json.number("latency_ms_median", at(0.5), 4).number("latency_ms_p99", at(0.99), 4).number("latency_ms_max", latency_ms.back(), 4);
  json.integer("last_tick", last->tick);
  std::printf("%s\n", json.str().c_str());
  return kExitOk;
}

}  // namespace ocean::admin
