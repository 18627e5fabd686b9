// towdb serve: the planner's web page and a JSON API over one database
// (issue 18 item 3), with cpp-httplib (Debian libcpp-httplib-dev).
//
//   towdb serve --db FILE [--port N] [--bind ADDR] [--rate-limit-per-s R] [--chart-js FILE]
//
//   GET  /                 the planner page (cli/web/planner.html): form, answer, three charts
//   GET  /chart.js         Chart.js from Debian's libjs-chart.js, served locally (no network)
//   GET  /api/vessels      the stored tug / tow / line combinations and their grid ranges
//   GET  /api/query?...    one answer, the JSON of `towdb query --json`
//   GET  /api/plan?...     the three curves of `towdb plan --json`
//   POST /api/query        a JSON object (one question) or array (up to 100): answers
//
// Question fields are the batch CSV columns of `towdb query --batch`
// (tug, tow, line, speed_kt, wind_kt, hs_ft, tp_s, heading_deg, length_ft,
// mean_tension_lbf, probability, tow_days, brake, spectrum). A bad request is
// answered 400 with {"error": message, "field": name}. Limits: the body of a
// request 64 KiB (413), the URI 8 KiB (cpp-httplib), R requests per second per
// client address with bursts of 2R (429). Binds 127.0.0.1 unless told;
// the database is opened read-only; one handle, used under a mutex.
#include <netdb.h>
#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <httplib.h>
#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "common/error.hpp"
#include "output.hpp"
#include "plan_curves.hpp"
#include "query_database.hpp"
#include "query_json.hpp"
#include "serve_page.hpp"
#include "store/database.hpp"

namespace towdb::cli {

namespace {

using nlohmann::json;
using nlohmann::ordered_json;

constexpr std::size_t kMaxBodyBytes = 64 * 1024;
constexpr std::size_t kMaxQuestionsPerPost = 100;
constexpr int kWorkerThreads = 8;
constexpr std::size_t kKeepAliveRequests = 100;

struct ServeArgs {
  std::string db, bind = "127.0.0.1", chart_js = TOWDB_CHART_JS_DEFAULT;
  int port = 8080;
  double rate_limit_per_s = 20.0;
};

// A bad request: its message names the field, the value and what is allowed.
struct BadRequest {
  std::string message, field;
};

const std::vector<std::string>& field_names() {
  static const std::vector<std::string> names = {
      "tug",         "tow",       "line",             "spectrum",    "speed_kt", "wind_kt",           "hs_ft",
      "tp_s",        "heading_deg", "length_ft",      "mean_tension_lbf", "probability", "tow_days", "brake",
      "curve_headings_deg"};
  return names;
}

// The field a library message names: its first word when that is a field,
// else the first field named anywhere in it as a whole word (a refusal of far
// extrapolation starts "extrapolated from speed_kt = ...").
std::string field_of(const std::string& message) {
  const std::string first = message.substr(0, message.find_first_of(" =:'"));
  for (const auto& f : field_names()) {
    if (f == first) return f;
  }
  auto ident = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  std::size_t best = std::string::npos;
  std::string found;
  for (const auto& f : field_names()) {
    for (std::size_t p = message.find(f); p != std::string::npos && p < best; p = message.find(f, p + 1)) {
      const bool whole = (p == 0 || !ident(message[p - 1])) &&
                         (p + f.size() >= message.size() || !ident(message[p + f.size()]));
      if (whole) {
        best = p;
        found = f;
        break;
      }
    }
  }
  return found;
}

double parse_field_number(const std::string& field, const std::string& text) {
  double v = 0.0;
  if (!parse_number(text, &v)) throw BadRequest{field + " = '" + text + "': not a finite number", field};
  return v;
}

// One question from name -> text pairs (query string or JSON values as text).
PlanQuestion to_question(const std::multimap<std::string, std::string>& params, bool need_all) {
  PlanQuestion q;
  q.samples = 31;
  for (const auto& [k, v] : params) {
    if (params.count(k) > 1) throw BadRequest{k + ": given " + std::to_string(params.count(k)) + " times", k};
    if (k == "tug") q.tug = v;
    else if (k == "tow") q.tow = v;
    else if (k == "line") q.line = v;
    else if (k == "speed_kt") q.speed_kt = parse_field_number(k, v);
    else if (k == "wind_kt") q.wind_kt = v.empty() ? q.wind_kt : parse_field_number(k, v);
    else if (k == "hs_ft") q.hs_ft = v.empty() ? q.hs_ft : parse_field_number(k, v);
    else if (k == "tp_s") q.tp_s = v.empty() ? q.tp_s : parse_field_number(k, v);
    else if (k == "heading_deg") q.heading_deg = parse_field_number(k, v);
    else if (k == "length_ft") q.length_ft = parse_field_number(k, v);
    else if (k == "mean_tension_lbf") q.mean_tension_lbf = v.empty() ? q.mean_tension_lbf : parse_field_number(k, v);
    else if (k == "probability") q.probability = parse_field_number(k, v);
    else if (k == "tow_days") q.tow_days = parse_field_number(k, v);
    else if (k == "brake") {
      if (v != "0" && v != "1" && v != "true" && v != "false") {
        throw BadRequest{"brake = '" + v + "': allowed: 0, 1, true or false", k};
      }
      q.brake = v == "1" || v == "true";
    } else if (k == "curve_headings_deg") {
      q.curve_headings_deg.clear();
      std::stringstream ss(v);
      for (std::string item; std::getline(ss, item, ',');) q.curve_headings_deg.push_back(parse_field_number(k, item));
      if (q.curve_headings_deg.empty() || q.curve_headings_deg.size() > 8) {
        throw BadRequest{k + " = '" + v + "': allowed: 1 to 8 comma-separated headings in [0, 360]", k};
      }
      for (double h : q.curve_headings_deg) {
        if (h < 0.0 || h > 360.0) throw BadRequest{k + " = '" + v + "': each heading must be in [0, 360] deg", k};
      }
    } else {
      std::string known;
      for (const auto& f : field_names()) known += (known.empty() ? "" : ", ") + f;
      // An empty name is named by what it is (tests/fuzz/regressions/http).
      const std::string name = k.empty() ? "(empty name)" : k;
      throw BadRequest{name + ": unknown field; allowed: " + known, name};
    }
  }
  for (const char* f : {"tug", "tow", "line"}) {
    const std::string& v = f == std::string("tug") ? q.tug : f == std::string("tow") ? q.tow : q.line;
    if (v.empty()) throw BadRequest{std::string(f) + ": required (a name)", f};
  }
  if (std::isnan(q.wind_kt) && std::isnan(q.hs_ft)) throw BadRequest{"wind_kt: required (or hs_ft)", "wind_kt"};
  if (need_all) {
    if (std::isnan(q.speed_kt)) throw BadRequest{"speed_kt: required (a number of kt)", "speed_kt"};
    if (std::isnan(q.heading_deg)) throw BadRequest{"heading_deg: required (0 = following seas)", "heading_deg"};
    if (std::isnan(q.length_ft)) throw BadRequest{"length_ft: required (a number of ft)", "length_ft"};
  }
  return q;
}

std::multimap<std::string, std::string> params_of(const json& object) {
  if (!object.is_object()) throw BadRequest{"body: each question must be a JSON object of fields", "body"};
  std::multimap<std::string, std::string> params;
  for (const auto& [k, v] : object.items()) {
    if (v.is_string()) params.emplace(k, v.get<std::string>());
    else if (v.is_number()) params.emplace(k, json(v.get<double>()).dump());
    else if (v.is_boolean()) params.emplace(k, v.get<bool>() ? "true" : "false");
    else if (!v.is_null()) throw BadRequest{k + " = " + v.dump() + ": allowed: a number or a string", k};
  }
  return params;
}

// Requests per second per client address, in a token bucket of 2R.
class RateLimiter {
 public:
  explicit RateLimiter(double per_s) : per_s_(per_s) {}
  bool allow(const std::string& address) {
    const auto now = std::chrono::steady_clock::now();
    std::lock_guard<std::mutex> lock(mutex_);
    Bucket& b = buckets_.try_emplace(address, Bucket{2.0 * per_s_, now}).first->second;
    const double elapsed_s = std::chrono::duration<double>(now - b.last).count();
    b.tokens = std::min(2.0 * per_s_, b.tokens + elapsed_s * per_s_);
    b.last = now;
    if (b.tokens < 1.0) return false;
    b.tokens -= 1.0;
    return true;
  }

 private:
  struct Bucket {
    double tokens;
    std::chrono::steady_clock::time_point last;
  };
  double per_s_;
  std::mutex mutex_;
  std::map<std::string, Bucket> buckets_;
};

// The stored tug / tow / line combinations and their grid ranges, read once
// from the cases table (schema/README.md) through a read-only connection.
ordered_json read_vessels(const std::string& db_path) {
  store::Database db = store::Database::open(db_path, store::Database::Mode::kReadOnly);
  store::Statement st = db.prepare(
      "SELECT tug_name, tow_name, line_type, MIN(speed_kt), MAX(speed_kt), MIN(wind_kt), MAX(wind_kt), "
      "MIN(hs_ft), MAX(hs_ft), MIN(length_ft), MAX(length_ft) FROM cases WHERE status = 'done' "
      "GROUP BY tug_name, tow_name, line_type ORDER BY tug_name, tow_name, line_type");
  ordered_json rows = ordered_json::array();
  auto range = [&](int col) {
    return st.is_null(col) ? ordered_json(nullptr)
                                  : ordered_json::array({st.column_double(col), st.column_double(col + 1)});
  };
  while (st.step()) {
    rows.push_back({{"tug", st.column_text(0)},
                    {"tow", st.column_text(1)},
                    {"line", st.column_text(2)},
                    {"speed_kt", range(3)},
                    {"wind_kt", range(5)},
                    {"hs_ft", range(7)},
                    {"length_ft", range(9)}});
  }
  return ordered_json{{"combinations", rows}};
}

std::string read_file(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw InputError("--chart-js = " + path + ": cannot read it (install Debian's libjs-chart.js)");
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

void send_json(httplib::Response& res, int status, const ordered_json& j) {
  res.status = status;
  // A request's bytes echoed in a message need not be UTF-8: they are written
  // as U+FFFD rather than failing the answer (tests/fuzz/regressions/http).
  res.set_content(j.dump(-1, ' ', false, ordered_json::error_handler_t::replace), "application/json");
}

void send_error(httplib::Response& res, int status, const std::string& message, const std::string& field) {
  send_json(res, status, ordered_json{{"error", message}, {"field", field.empty() ? ordered_json(nullptr) : ordered_json(field)}});
}

class Server {
 public:
  Server(const ServeArgs& a, std::unique_ptr<query::Database> db)
      : db_(std::move(db)), rate_limit_per_s_(a.rate_limit_per_s), limiter_(a.rate_limit_per_s),
        chart_js_(read_file(a.chart_js)), vessels_(read_vessels(a.db)) {}

  void install(httplib::Server& svr) {
    svr.new_task_queue = [] { return new httplib::ThreadPool(kWorkerThreads); };
    svr.set_payload_max_length(kMaxBodyBytes);
    svr.set_tcp_nodelay(true);  // small JSON answers: no 40 ms wait for a delayed ACK (Nagle)
    // A client keeps its connection for 100 requests (cpp-httplib's default is 5), so it
    // reconnects less: Debian's library listens with a backlog of 5 (compiled in), and a
    // connection dropped past it waits for the client's 1 s SYN retry (docs/performance.md).
    svr.set_keep_alive_max_count(kKeepAliveRequests);
    svr.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
      if (limiter_.allow(req.remote_addr)) return httplib::Server::HandlerResponse::Unhandled;
      res.set_header("Retry-After", "1");
      send_error(res, 429, "too many requests from " + req.remote_addr + ": the limit is " +
                               fmt(rate_limit_per_s_) + " per second", "");
      return httplib::Server::HandlerResponse::Handled;
    });
    svr.Get("/", [](const httplib::Request&, httplib::Response& res) {
      res.set_content(kServePageHtml, "text/html; charset=utf-8");
    });
    svr.Get("/chart.js", [this](const httplib::Request&, httplib::Response& res) {
      res.set_content(chart_js_, "application/javascript");
    });
    svr.Get("/api/vessels", [this](const httplib::Request&, httplib::Response& res) { send_json(res, 200, vessels_); });
    svr.Get("/api/query", [this](const httplib::Request& req, httplib::Response& res) {
      answer(res, [&] { return one_answer(to_question(req.params, true)); });
    });
    svr.Get("/api/plan", [this](const httplib::Request& req, httplib::Response& res) {
      answer(res, [&] {
        const PlanQuestion q = to_question(req.params, true);
        std::lock_guard<std::mutex> lock(mutex_);
        return plan_json(make_plan(*db_, q));
      });
    });
    svr.Post("/api/query", [this](const httplib::Request& req, httplib::Response& res) {
      answer(res, [&] { return post_answers(req.body); });
    });
    svr.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr) {
      send_error(res, 500, "internal error", "");
    });
    // Errors of the HTTP layer itself (a request it cannot parse, a path the
    // API does not have) are answered in the API's JSON too.
    svr.set_error_handler([](const httplib::Request& req, httplib::Response& res) {
      if (!res.body.empty()) return;
      if (res.status == 404) {
        send_error(res, 404, "path: no such page or API: " + req.path, "path");
      } else {
        send_error(res, res.status, "request: not a request this server can read (HTTP " +
                                        std::to_string(res.status) + ")", "request");
      }
    });
  }

 private:
  ordered_json one_answer(const PlanQuestion& q) {
    const query::QueryRequest r = to_request(q);
    std::lock_guard<std::mutex> lock(mutex_);
    return query_answer_json(r, db_->query(r), q.brake);
  }

  ordered_json post_answers(const std::string& body) {
    const json parsed = json::parse(body, nullptr, false);
    if (parsed.is_discarded()) throw BadRequest{"body: not valid JSON", "body"};
    if (!parsed.is_array()) return one_answer(to_question(params_of(parsed), true));
    if (parsed.size() > kMaxQuestionsPerPost) {
      throw BadRequest{"body: " + std::to_string(parsed.size()) + " questions; allowed: at most " +
                           std::to_string(kMaxQuestionsPerPost),
                       "body"};
    }
    ordered_json out = ordered_json::array();
    for (const json& item : parsed) {
      try {
        out.push_back(one_answer(to_question(params_of(item), true)));
      } catch (const BadRequest& e) {
        out.push_back({{"error", e.message}, {"field", e.field}});
      } catch (const query::QueryError& e) {
        if (!e.is_input()) throw;
        out.push_back({{"error", e.what()}, {"field", field_of(e.what())}});
      }
    }
    return out;
  }

  // Runs fn; bad input is 400 with the field named, anything else 500.
  template <typename Fn>
  void answer(httplib::Response& res, Fn&& fn) {
    try {
      send_json(res, 200, fn());
    } catch (const BadRequest& e) {
      send_error(res, 400, e.message, e.field);
    } catch (const query::QueryError& e) {
      if (e.is_input()) send_error(res, 400, e.what(), field_of(e.what()));
      else send_error(res, 500, e.what(), "");
    } catch (const InputError& e) {
      send_error(res, 400, e.what(), field_of(e.what()));
    } catch (const std::exception& e) {
      send_error(res, 500, e.what(), "");
    }
  }

  std::unique_ptr<query::Database> db_;
  std::mutex mutex_;  // the handle is used by one thread at a time (query.h)
  double rate_limit_per_s_;
  RateLimiter limiter_;
  std::string chart_js_;
  ordered_json vessels_;
};

// Stops the server on SIGINT or SIGTERM, from a thread that waits for them
// (blocked in every other thread), so no work happens in a signal handler.
std::thread stop_on_signal(httplib::Server& svr, sigset_t signals) {
  return std::thread([&svr, signals] {
    int sig = 0;
    sigwait(&signals, &sig);
    svr.stop();
  });
}

// --bind must name an address of this machine: a name the resolver does not
// know, or an address no interface has, is bad input (exit 2), seen by
// binding a socket to it on an ephemeral port. A failure to listen later (the
// port in use) is not the user's flag: exit 1.
void check_bind_address(const std::string& address) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = AI_PASSIVE;
  addrinfo* found = nullptr;
  const int rc = getaddrinfo(address.c_str(), "0", &hints, &found);
  if (rc != 0 || !found) {
    throw InputError("--bind = " + address + ": not an address (" + gai_strerror(rc) +
                     "); give one of this machine's, e.g. 127.0.0.1, 0.0.0.0 or ::1");
  }
  const int fd = socket(found->ai_family, found->ai_socktype, found->ai_protocol);
  const bool bound = fd >= 0 && bind(fd, found->ai_addr, found->ai_addrlen) == 0;
  const int bind_errno = errno;
  if (fd >= 0) close(fd);
  freeaddrinfo(found);
  if (!bound && bind_errno == EADDRNOTAVAIL) {
    throw InputError("--bind = " + address + ": no interface of this machine has this address; give one of its "
                     "own, e.g. 127.0.0.1, 0.0.0.0 or ::1");
  }
}

int run_serve(const ServeArgs& a) {
  check_bind_address(a.bind);
  std::unique_ptr<query::Database> db = open_query_database("--db", a.db);
  const int cases = db->case_count();
  Server server(a, std::move(db));
  httplib::Server svr;
  server.install(svr);
  int port = a.port;
  if (port == 0) {
    port = svr.bind_to_any_port(a.bind);
  } else if (!svr.bind_to_port(a.bind, port)) {
    port = -1;
  }
  if (port < 0) {
    throw Error("cannot listen on " + a.bind + ":" + std::to_string(a.port) + " (the port is in use?)");
  }
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  std::thread stopper = stop_on_signal(svr, signals);
  std::cout << "towdb serve: http://" << a.bind << ":" << port << "/ (" << a.db << ", " << cases
            << " cases, read-only); Ctrl-C stops" << std::endl;
  const bool listened = svr.listen_after_bind();
  if (stopper.joinable()) {
    if (listened) {
      stopper.join();
    } else {
      pthread_kill(stopper.native_handle(), SIGTERM);
      stopper.join();
    }
  }
  std::cout << "towdb serve: stopped" << std::endl;
  return 0;
}

}  // namespace

void add_serve_command(CLI::App& app, Context& ctx) {
  auto a = std::make_shared<ServeArgs>();
  CLI::App* c = app.add_subcommand("serve", "The planner's web page and JSON API over a database (local)");
  c->add_option("--db", a->db, "towdb database file (opened read-only)")->required();
  c->add_option("--port", a->port, "TCP port (default 8080; 0: any free port, printed)")
      ->check(CLI::Range(0, 65535));
  c->add_option("--bind", a->bind, "Address to listen on (default 127.0.0.1: this machine only)");
  c->add_option("--rate-limit-per-s", a->rate_limit_per_s,
                "Requests per second per client address, bursts of twice that (default 20)")
      ->check(number_in(0.0, 1e6, true, false));
  c->add_option("--chart-js", a->chart_js, "Chart.js file to serve (default: Debian's libjs-chart.js)");
  c->callback([&ctx, a] { ctx.action = [a] { return run_serve(*a); }; });
}

}  // namespace towdb::cli
