// A replay server on a free localhost port, served from a thread for the length of a test, with
// an HTTP client (cpp-httplib) that adds the token: the server tested in-process, as a browser
// would reach it.
#pragma once

#include <memory>
#include <string>
#include <thread>

#include "apps/replay/replay_server.h"

// Last: its system headers' macros break Eigen's templates when included first.
#include <httplib.h>

namespace vascsim::replay::testing {

class LiveServer {
 public:
  explicit LiveServer(const ReplayOptions& options) : server_(options) {
    thread_ = std::thread([this] { server_.serve(); });
    client_ = std::make_unique<httplib::Client>("127.0.0.1", server_.port());
    client_->set_read_timeout(120);
  }
  ~LiveServer() {
    server_.stop();
    thread_.join();
  }
  // GET with the token appended (unless `with_token` is false).
  httplib::Result get(const std::string& path_and_query, bool with_token = true) {
    return client_->Get(with_token ? authorised(path_and_query).c_str() : path_and_query.c_str());
  }
  httplib::Result post(const std::string& path_and_query, const std::string& body) {
    return client_->Post(authorised(path_and_query).c_str(), body, "application/json");
  }
  std::string authorised(const std::string& path_and_query) const {
    return path_and_query + (path_and_query.find('?') == std::string::npos ? "?" : "&") + "token=" + server_.token();
  }
  ReplayServer& server() { return server_; }
  httplib::Client& client() { return *client_; }

 private:
  ReplayServer server_;
  std::thread thread_;
  std::unique_ptr<httplib::Client> client_;
};

}  // namespace vascsim::replay::testing
