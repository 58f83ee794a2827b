// The replay server's request parameters, parsed and validated in one place so every handler
// stays thin: a missing or bad parameter becomes a ParamError naming it, which the server
// answers with status 400 and {"error": ..., "parameter": NAME}. Independent of the HTTP library
// (a multimap of query parameters in), so it is tested without a socket.
#pragma once

#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/view.h"

namespace vascsim::replay {

class ParamError : public std::runtime_error {
 public:
  ParamError(std::string parameter, const std::string& message)
      : std::runtime_error(parameter + ": " + message), parameter_(std::move(parameter)) {}
  const std::string& parameter() const { return parameter_; }

 private:
  std::string parameter_;
};

class RequestParams {
 public:
  // `query`: the URL's query parameters only (query_of in replay_server.cpp), not fields of a
  // form-encoded body, which the HTTP library would mix in.
  explicit RequestParams(std::multimap<std::string, std::string> query) : query_(std::move(query)) {}

  // The first value of `name`, if given; longer than 4096 characters is an error.
  std::optional<std::string> text(const std::string& name) const;
  // A finite number in [min, max], or `fallback` when absent.
  double number(const std::string& name, double fallback, double min, double max) const;
  std::optional<double> optional_number(const std::string& name, double min, double max) const;
  long long integer(const std::string& name, long long fallback, long long min, long long max) const;
  // One of `choices`, or `fallback` when absent.
  std::string choice(const std::string& name, const std::string& fallback, const std::vector<std::string>& choices) const;

 private:
  std::multimap<std::string, std::string> query_;
};

// Largest frame the server renders, px per side.
inline constexpr int kMaxFrameSide = 4096;

// The view parameters of /api/frame.png and /api/export: width, height, camera, zoom, center,
// layers. Absent ones keep the defaults of render::View.
render::View parse_view(const RequestParams& params);

}  // namespace vascsim::replay
