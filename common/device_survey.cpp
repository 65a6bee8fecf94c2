#include "device_survey.hpp"

#include <algorithm>

namespace glpt {
namespace {

constexpr std::string_view kListSeparator = "; ";

std::string clean(std::string value) {
  std::replace_if(
      value.begin(), value.end(), [](char c) { return c == '\t' || c == '\n'; }, ' ');
  return value;
}

std::string join(const std::vector<std::string>& parts) {
  std::string joined;
  for (const std::string& part : parts) {
    if (!joined.empty()) joined += kListSeparator;
    joined += part;
  }
  return clean(joined);
}

std::vector<std::string> split(std::string_view text, std::string_view separator) {
  std::vector<std::string> parts;
  if (text.empty()) return parts;
  for (size_t start = 0;;) {
    const size_t end = text.find(separator, start);
    parts.emplace_back(text.substr(start, end - start));
    if (end == std::string_view::npos) break;
    start = end + separator.size();
  }
  return parts;
}

}  // namespace

const DeviceSurvey::Device* DeviceSurvey::chosen() const {
  const auto it =
      std::find_if(devices.begin(), devices.end(), [](const Device& d) { return d.chosen; });
  return it == devices.end() ? nullptr : &*it;
}

std::string encode_device_survey(const DeviceSurvey& survey) {
  std::string text = "glpt-device-survey\t1\n";
  text += "loader\t" + clean(survey.loader_version) + "\n";
  text += "validation_layer\t" + std::string(survey.validation_layer ? "1" : "0") + "\n";
  if (!survey.instance_error.empty())
    text += "instance_error\t" + clean(survey.instance_error) + "\n";
  if (!survey.choice_error.empty()) text += "choice_error\t" + clean(survey.choice_error) + "\n";
  for (const DeviceSurvey::Device& d : survey.devices) {
    text += "device\t" + clean(d.name) + "\t" + clean(d.type) + "\t" + clean(d.driver) + "\t" +
            clean(d.api_version) + "\t" + join(d.missing) + "\t" + join(d.missing_ray_query) +
            "\t" + (d.geometry_shader ? "1" : "0") + (d.storage_image_read ? "1" : "0") +
            (d.storage_image_write ? "1" : "0") + (d.chosen ? "1" : "0") + "\n";
  }
  return text;
}

std::optional<DeviceSurvey> decode_device_survey(std::string_view text) {
  const std::vector<std::string> lines = split(text, "\n");
  if (lines.empty() || lines[0] != "glpt-device-survey\t1") return std::nullopt;
  DeviceSurvey survey;
  for (size_t i = 1; i < lines.size(); ++i) {
    if (lines[i].empty()) continue;
    const std::vector<std::string> f = split(lines[i], "\t");
    const std::string value = f.size() > 1 ? f[1] : std::string();
    if (f[0] == "loader" && f.size() == 2) {
      survey.loader_version = value;
    } else if (f[0] == "validation_layer" && f.size() == 2) {
      survey.validation_layer = value == "1";
    } else if (f[0] == "instance_error" && f.size() == 2) {
      survey.instance_error = value;
    } else if (f[0] == "choice_error" && f.size() == 2) {
      survey.choice_error = value;
    } else if (f[0] == "device" && f.size() == 8 && f[7].size() == 4) {
      DeviceSurvey::Device& d = survey.devices.emplace_back();
      d.name = f[1];
      d.type = f[2];
      d.driver = f[3];
      d.api_version = f[4];
      d.missing = split(f[5], kListSeparator);
      d.missing_ray_query = split(f[6], kListSeparator);
      d.geometry_shader = f[7][0] == '1';
      d.storage_image_read = f[7][1] == '1';
      d.storage_image_write = f[7][2] == '1';
      d.chosen = f[7][3] == '1';
    } else {
      return std::nullopt;
    }
  }
  return survey;
}

}  // namespace glpt
