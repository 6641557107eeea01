#include "cli/client_commands.hpp"

#include <openssl/evp.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cli/http_client.hpp"
#include "cli/job_outcome.hpp"
#include "cli/parameter_table.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace kontakt::cli {

namespace {

constexpr const char* kCommands[] = {"submit", "sweep", "status", "logs", "wait", "cancel", "fetch", "list"};
constexpr auto kPollInterval = std::chrono::milliseconds(250);

/// The options every daemon command understands, plus what is left for the command itself.
struct CommonArgs {
  std::string server, token;
  bool json = false;
  std::vector<std::string> rest;  ///< positional arguments and command options, in order
};

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Refused by the daemon: carries the problem's detail and the HTTP status.
class ApiError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The daemon refused the deck (422 input_error): the message lists file:line: keyword: ...
class DeckRejected : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

std::string env_or(const char* name, const std::string& fallback) {
  const char* v = std::getenv(name);
  return v && *v ? v : fallback;
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UsageError("cannot read " + path.string());
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

CommonArgs parse_common(int argc, char** argv) {
  CommonArgs args;
  args.server = env_or("KONTAKT_SERVER", "http://127.0.0.1:8080");
  args.token = env_or("KONTAKT_TOKEN", "");
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw UsageError(a + " needs a value");
      return argv[++i];
    };
    if (a == "--server") args.server = value();
    else if (a == "--token") args.token = value();
    else if (a == "--token-file") {
      std::string t = read_file(value());
      t = t.substr(0, t.find('\n'));
      args.token = t;
    } else if (a == "--json") args.json = true;
    else args.rest.push_back(a);
  }
  return args;
}

/// Takes "--flag VALUE" out of `rest`; nullopt when absent.
std::optional<std::string> take_option(std::vector<std::string>& rest, const std::string& flag) {
  for (std::size_t i = 0; i < rest.size(); ++i) {
    if (rest[i] != flag) continue;
    if (i + 1 >= rest.size()) throw UsageError(flag + " needs a value");
    std::string v = rest[i + 1];
    rest.erase(rest.begin() + static_cast<long>(i), rest.begin() + static_cast<long>(i) + 2);
    return v;
  }
  return std::nullopt;
}

std::vector<std::string> take_all(std::vector<std::string>& rest, const std::string& flag) {
  std::vector<std::string> values;
  while (auto v = take_option(rest, flag)) values.push_back(*v);
  return values;
}

bool take_flag(std::vector<std::string>& rest, const std::string& flag) {
  for (std::size_t i = 0; i < rest.size(); ++i)
    if (rest[i] == flag) {
      rest.erase(rest.begin() + static_cast<long>(i));
      return true;
    }
  return false;
}

/// The one positional argument left (a job id or a deck); refuses unknown options.
std::string take_positional(std::vector<std::string>& rest, const char* what) {
  for (const auto& a : rest)
    if (a.size() > 1 && a[0] == '-') throw UsageError("unknown option " + a);
  if (rest.size() != 1) throw UsageError(std::string("expected one ") + what);
  return rest.front();
}

std::string percent_encode(const std::string& s) {
  std::string out;
  for (unsigned char c : s) {
    if (std::isalnum(c) || std::strchr("-_.~", c)) {
      out += static_cast<char>(c);
    } else {
      char hex[4];
      std::snprintf(hex, sizeof hex, "%%%02X", c);
      out += hex;
    }
  }
  return out;
}

/// The JSON body of a 2xx reply; throws ApiError with the problem detail otherwise.
json expect_json(const HttpReply& reply) {
  const json body = json::parse(reply.body, nullptr, false);
  if (reply.status == 422 && body.is_object() && body.value("code", "") == "input_error") {
    std::string lines;
    for (const json& e : body.value("errors", json::array())) {
      if (e.contains("row")) lines += "row " + e["row"].dump() + ": ";  // a sweep's row
      lines += e.value("message", "") + "\n";
    }
    if (!lines.empty()) lines.pop_back();
    throw DeckRejected(lines.empty() ? body.value("detail", "") : lines);
  }
  if (reply.status >= 300) {
    std::string detail = body.is_object() ? body.value("detail", "") : "";
    if (detail.empty()) detail = reply.body.substr(0, 200);
    throw ApiError("HTTP " + std::to_string(reply.status) + ": " + detail);
  }
  if (body.is_discarded()) throw TransportError("the daemon sent no JSON");
  return body;
}

json get_job(HttpClient& client, const std::string& id) {
  return expect_json(client.request("GET", "/v1/jobs/" + percent_encode(id)));
}

void print_status(const json& job, bool as_json) {
  if (as_json) {
    std::printf("%s\n", job.dump().c_str());
    return;
  }
  std::string reason;
  if (job["reason"].is_object()) reason = "  " + job["reason"].value("code", "") + ": " + job["reason"].value("message", "");
  std::printf("%s  %s  %s%s\n", job.value("id", "").c_str(), job.value("name", "").c_str(),
              progress_line(job, 20).c_str(), reason.c_str());
}

/// Polls until the job is finished; on a TTY redraws one progress line.
int wait_for(HttpClient& client, const std::string& id, std::optional<double> timeout, bool as_json) {
  const bool tty = isatty(fileno(stderr)) != 0;
  const auto start = std::chrono::steady_clock::now();
  std::string last_line;
  while (true) {
    const json job = get_job(client, id);
    const std::string status = job.value("status", "");
    const bool done = status == "succeeded" || status == "failed" || status == "canceled";
    const std::string line = progress_line(job, 30);
    if (tty) std::fprintf(stderr, "\r%s\033[K", line.c_str());
    else if (line != last_line && done) std::fprintf(stderr, "%s\n", line.c_str());
    last_line = line;
    if (done) {
      if (tty) std::fputc('\n', stderr);
      print_status(job, as_json);
      return exit_code_for_job(job);
    }
    const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (timeout && waited > *timeout) {
      if (tty) std::fputc('\n', stderr);
      std::fprintf(stderr, "kontakt: job %s still %s after %g s\n", id.c_str(), status.c_str(), *timeout);
      return kWaitTimeout;
    }
    std::this_thread::sleep_for(kPollInterval);
  }
}

std::optional<double> take_timeout(std::vector<std::string>& rest) {
  const auto text = take_option(rest, "--timeout");
  if (!text) return std::nullopt;
  char* end = nullptr;
  const double t = std::strtod(text->c_str(), &end);
  if (*end || t <= 0) throw UsageError("--timeout takes a number of seconds");
  return t;
}

int cmd_submit(HttpClient& client, CommonArgs& args) {
  const auto name = take_option(args.rest, "--name");
  const auto scheme = take_option(args.rest, "--scheme");
  const auto main = take_option(args.rest, "--main");
  const auto key = take_option(args.rest, "--idempotency-key");
  const auto labels = take_all(args.rest, "--label");
  const bool wait = take_flag(args.rest, "--wait");
  const auto timeout = take_timeout(args.rest);
  const fs::path deck = take_positional(args.rest, "deck (.inp or .zip)");
  const bool zip = deck.extension() == ".zip";
  std::string target = "/v1/jobs?";
  auto add = [&](const char* k, const std::string& v) { target += std::string(k) + "=" + percent_encode(v) + "&"; };
  if (name) add("name", *name);
  if (scheme) add("scheme", *scheme);
  if (main || !zip) add("main", main.value_or(deck.filename().string()));  // zip: the only deck
  for (const auto& l : labels) add("label", l);
  target.pop_back();
  std::map<std::string, std::string> headers;
  if (key) headers["Idempotency-Key"] = *key;
  const json job = expect_json(client.request("POST", target, read_file(deck),
                                              zip ? "application/zip" : "text/plain", headers));
  const std::string id = job.value("id", "");
  if (!wait) {
    if (args.json) std::printf("%s\n", job.dump().c_str());
    else std::printf("%s\n", id.c_str());
    return kSucceeded;
  }
  std::fprintf(stderr, "kontakt: submitted %s\n", id.c_str());
  return wait_for(client, id, timeout, args.json);
}

int cmd_status(HttpClient& client, CommonArgs& args) {
  print_status(get_job(client, take_positional(args.rest, "job id")), args.json);
  return kSucceeded;
}

int cmd_wait(HttpClient& client, CommonArgs& args) {
  const auto timeout = take_timeout(args.rest);
  return wait_for(client, take_positional(args.rest, "job id"), timeout, args.json);
}

int cmd_cancel(HttpClient& client, CommonArgs& args) {
  const std::string id = take_positional(args.rest, "job id");
  print_status(expect_json(client.request("POST", "/v1/jobs/" + percent_encode(id) + "/cancel")), args.json);
  return kSucceeded;
}

/// Prints the job's events as JSON lines (SSE data); -f follows them until the job ends.
int cmd_logs(HttpClient& client, CommonArgs& args) {
  const bool follow = take_flag(args.rest, "-f") || take_flag(args.rest, "--follow");
  const std::string id = take_positional(args.rest, "job id");
  std::string pending;
  const HttpReply reply = client.stream(
      "/v1/jobs/" + percent_encode(id) + "/events?follow=" + (follow ? "true" : "false"), {},
      [&](std::string_view data) {
        pending.append(data);
        for (std::size_t nl; (nl = pending.find('\n')) != std::string::npos; pending.erase(0, nl + 1)) {
          const std::string line = pending.substr(0, nl);
          if (line.rfind("data: ", 0) == 0) std::printf("%s\n", line.c_str() + 6);
        }
        std::fflush(stdout);
        return true;
      },
      std::chrono::seconds(60));
  if (reply.status >= 300) expect_json(reply);
  return kSucceeded;
}

/// Downloads while hashing; throws when the sha256 differs from the listing's.
void download(HttpClient& client, const std::string& id, const json& artifact, const fs::path& dir) {
  const std::string name = artifact.value("name", "");
  if (name.empty() || name.find('/') != std::string::npos || name == "..")
    throw TransportError("the daemon listed an unsafe file name '" + name + "'");
  const fs::path partial = dir / (name + ".download");
  std::ofstream out(partial, std::ios::binary);
  if (!out) throw UsageError("cannot write " + partial.string());
  std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> sha(EVP_MD_CTX_new(), EVP_MD_CTX_free);
  EVP_DigestInit_ex(sha.get(), EVP_sha256(), nullptr);
  const HttpReply reply = client.stream(
      "/v1/jobs/" + percent_encode(id) + "/results/" + percent_encode(name), {},
      [&](std::string_view data) {
        out.write(data.data(), static_cast<std::streamsize>(data.size()));
        EVP_DigestUpdate(sha.get(), data.data(), data.size());
        return true;
      },
      std::chrono::seconds(60));
  out.close();
  if (reply.status >= 300) {
    fs::remove(partial);
    expect_json(reply);
  }
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int n = 0;
  EVP_DigestFinal_ex(sha.get(), digest, &n);
  std::string hex;
  for (unsigned int i = 0; i < n; ++i) {
    char b[3];
    std::snprintf(b, sizeof b, "%02x", digest[i]);
    hex += b;
  }
  if (hex != artifact.value("sha256", "")) {
    fs::remove(partial);
    throw TransportError(name + ": checksum mismatch (got " + hex + ")");
  }
  fs::rename(partial, dir / name);
  std::printf("%s\n", (dir / name).c_str());
}

int cmd_fetch(HttpClient& client, CommonArgs& args) {
  const fs::path dir = take_option(args.rest, "-o").value_or(".");
  std::vector<std::string> wanted;
  std::string id;
  for (const auto& a : args.rest) {
    if (a.size() > 1 && a[0] == '-') throw UsageError("unknown option " + a);
    if (id.empty()) id = a;
    else wanted.push_back(a);
  }
  if (id.empty()) throw UsageError("expected a job id");
  fs::create_directories(dir);
  const json list = expect_json(client.request("GET", "/v1/jobs/" + percent_encode(id) + "/results"));
  int n = 0;
  for (const json& artifact : list.at("artifacts")) {
    const std::string name = artifact.value("name", "");
    if (!wanted.empty() && std::find(wanted.begin(), wanted.end(), name) == wanted.end()) continue;
    download(client, id, artifact, dir);
    ++n;
  }
  if (n == 0) {
    std::fprintf(stderr, "kontakt: job %s has no matching results (yet)\n", id.c_str());
    return kFailed;
  }
  return kSucceeded;
}

int cmd_list(HttpClient& client, CommonArgs& args) {
  const auto status = take_option(args.rest, "--status");
  const auto limit = take_option(args.rest, "--limit");
  const auto labels = take_all(args.rest, "--label");
  if (!args.rest.empty()) throw UsageError("unknown argument " + args.rest.front());
  std::string query = "limit=" + percent_encode(limit.value_or("50"));
  if (status) query += "&status=" + percent_encode(*status);
  for (const auto& l : labels) query += "&label=" + percent_encode(l);
  const json page = expect_json(client.request("GET", "/v1/jobs?" + query));
  if (args.json) {
    std::printf("%s\n", page.dump().c_str());
    return kSucceeded;
  }
  for (const json& job : page.at("jobs"))
    std::printf("%s  %-9s  %-24s  %s  %3.0f%%\n", job.value("id", "").c_str(),
                job.value("status", "").c_str(), job.value("name", "").substr(0, 24).c_str(),
                job.value("created", "").c_str(), job["progress"].value("percent", 0.0));
  if (page["next_page_token"].is_string())
    std::printf("(more: --limit, or GET /v1/jobs?page_token=%s)\n",
                page["next_page_token"].get<std::string>().c_str());
  return kSucceeded;
}

/// Polls the sweep until every job of it has ended; prints one line per job. The exit code:
/// the highest of its jobs' (`wait`'s codes): 0 only when every job succeeded.
int wait_for_sweep(HttpClient& client, const std::string& id, std::optional<double> timeout,
                   bool as_json) {
  const auto start = std::chrono::steady_clock::now();
  const std::string path = "/v1/sweeps/id/" + percent_encode(id);
  while (true) {
    const json sweep = expect_json(client.request("GET", path));
    if (sweep.value("status", "") == "finished") break;
    const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (timeout && waited > *timeout) {
      std::fprintf(stderr, "kontakt: sweep %s still running after %g s\n", id.c_str(), *timeout);
      return kWaitTimeout;
    }
    std::this_thread::sleep_for(kPollInterval);
  }
  const json jobs = expect_json(client.request("GET", path + "/jobs"));
  int code = kSucceeded;
  for (const json& job : jobs["jobs"]) {
    const std::string status = job.value("status", "");
    const std::string reason = job["reason"].is_string() ? job["reason"].get<std::string>() : "";
    if (as_json) std::printf("%s\n", job.dump().c_str());
    else
      std::printf("%4d  %s  %-9s  %s\n", job.value("row", 0), job.value("id", "").c_str(),
                  status.c_str(), reason.c_str());
    const int job_code = exit_code_for_job({{"status", status}, {"reason", {{"code", reason}}}});
    code = std::max(code, job_code);
  }
  return code;
}

int cmd_sweep(HttpClient& client, CommonArgs& args) {
  const auto name = take_option(args.rest, "--name");
  const auto scheme = take_option(args.rest, "--scheme");
  const auto key = take_option(args.rest, "--idempotency-key");
  const auto max_parallel = take_option(args.rest, "--max-parallel");
  const auto labels = take_all(args.rest, "--label");
  const bool wait = take_flag(args.rest, "--wait");
  const auto timeout = take_timeout(args.rest);
  for (const auto& a : args.rest)
    if (a.size() > 1 && a[0] == '-') throw UsageError("unknown option " + a);
  if (args.rest.size() != 2) throw UsageError("expected TEMPLATE.inp PARAMS.csv");
  const fs::path table_file = args.rest[1];
  json body{{"template", read_file(args.rest[0])}};
  try {
    body["rows"] = parse_parameter_table(read_file(table_file));
  } catch (const TableError& e) {
    throw UsageError(table_file.string() + ": " + e.what());
  }
  if (name) body["name"] = *name;
  if (scheme) body["scheme"] = *scheme;
  if (max_parallel) {
    char* end = nullptr;
    const long n = std::strtol(max_parallel->c_str(), &end, 10);
    if (*end || n < 1) throw UsageError("--max-parallel takes a positive whole number");
    body["max_parallel"] = n;
  }
  for (const std::string& l : labels) {
    const std::size_t eq = l.find('=');
    if (eq == std::string::npos) throw UsageError("--label takes key=value, not " + l);
    body["labels"][l.substr(0, eq)] = l.substr(eq + 1);
  }
  std::map<std::string, std::string> headers;
  if (key) headers["Idempotency-Key"] = *key;
  const json sweep =
      expect_json(client.request("POST", "/v1/sweeps", body.dump(), "application/json", headers));
  const std::string id = sweep.value("id", "");
  if (!wait) {
    if (args.json) std::printf("%s\n", sweep.dump().c_str());
    else std::printf("%s\n", id.c_str());
    return kSucceeded;
  }
  std::fprintf(stderr, "kontakt: sweep %s: %d jobs\n", id.c_str(), sweep.value("rows", 0));
  return wait_for_sweep(client, id, timeout, args.json);
}

}  // namespace

bool is_client_command(const char* name) {
  for (const char* c : kCommands)
    if (!std::strcmp(c, name)) return true;
  return false;
}

void print_client_usage(std::FILE* out) {
  std::fputs(
      "daemon commands (--server URL or KONTAKT_SERVER, default http://127.0.0.1:8080;\n"
      "                 --token T | --token-file F or KONTAKT_TOKEN; --json for JSON output):\n"
      "  kontakt submit DECK.inp|DECK.zip [--name N] [--scheme S] [--label k=v]... [--main F]\n"
      "                 [--idempotency-key K] [--wait [--timeout S]]     prints the job id\n"
      "  kontakt sweep TEMPLATE.inp PARAMS.csv [--max-parallel N] [--name N] [--scheme S]\n"
      "                 [--label k=v]... [--idempotency-key K] [--wait [--timeout S]]\n"
      "                 one job per CSV row (header: the template's <name> placeholders);\n"
      "                 prints the sweep id; --wait: one line per job, the highest exit code\n"
      "  kontakt status ID            one line: status, step, increment, iteration, progress\n"
      "  kontakt wait ID [--timeout S]  until the job ends (a progress line on a TTY)\n"
      "  kontakt logs ID [-f]         the job's events as JSON lines; -f follows them live\n"
      "  kontakt cancel ID            cancel (idempotent)\n"
      "  kontakt fetch ID [NAME...] [-o DIR]  download results, sha256-checked\n"
      "  kontakt list [--status S[,S]] [--label k=v] [--limit N]\n"
      "  exit codes of wait and submit --wait: 0 succeeded, 2 input error (also when submit is\n"
      "  refused for a bad deck), 3 not converged, 4 failed otherwise, 5 canceled, 6 daemon\n"
      "  unreachable or request refused, 7 timeout; other commands: 0, 1 usage, 6\n",
      out);
}

int client_command(int argc, char** argv) {
  const std::string command = argv[1];
  try {
    CommonArgs args = parse_common(argc, argv);
    HttpClient client(args.server, args.token, std::chrono::seconds(30));
    if (command == "submit") return cmd_submit(client, args);
    if (command == "sweep") return cmd_sweep(client, args);
    if (command == "status") return cmd_status(client, args);
    if (command == "wait") return cmd_wait(client, args);
    if (command == "cancel") return cmd_cancel(client, args);
    if (command == "logs") return cmd_logs(client, args);
    if (command == "fetch") return cmd_fetch(client, args);
    return cmd_list(client, args);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "kontakt %s: %s\n", command.c_str(), e.what());
    return kUsage;
  } catch (const DeckRejected& e) {
    std::fprintf(stderr, "kontakt %s: the deck was refused:\n%s\n", command.c_str(), e.what());
    return kInputError;
  } catch (const std::exception& e) {  // TransportError, ApiError, a malformed reply
    std::fprintf(stderr, "kontakt %s: %s\n", command.c_str(), e.what());
    return kTransport;
  }
}

}  // namespace kontakt::cli
