// The case file loader rejects every schema violation with a message that
// names the key and the allowed range (SPEC §2), and reads the default case.

#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "case_file.hpp"

namespace rsi {
namespace {

using nlohmann::json;

const std::string default_path = std::string(RSI_SOURCE_DIR) + "/data/cases/batailly2007.json";

json default_document() {
  std::ifstream in(default_path);
  return json::parse(in);
}

/// parse_case must throw CaseError whose message contains every fragment.
void expect_rejected(const json& document, const std::vector<std::string>& fragments) {
  try {
    parse_case(document, "test.json");
    ADD_FAILURE() << "accepted: " << document.dump();
  } catch (const CaseError& e) {
    const std::string message = e.what();
    std::printf("rejected: %s\n", message.c_str());
    for (const std::string& f : fragments)
      EXPECT_NE(message.find(f), std::string::npos) << message;
  }
}

TEST(CaseFile, ReadsTheDefaultCase) {
  const Case c = load_case(default_path);
  EXPECT_EQ(c.bladed_disk.n_blades, 22);
  EXPECT_EQ(c.casing.n_elements, 40);
  // Degrees in the file, radians in memory: 1 degree and 180 degrees.
  EXPECT_DOUBLE_EQ(c.bladed_disk.kink_angle, M_PI / 180.0);
  EXPECT_DOUBLE_EQ(c.casing.clamp_angle, M_PI);
  EXPECT_DOUBLE_EQ(c.casing.radius - c.bladed_disk.tip_radius, 0.501 - 0.500);
}

TEST(CaseFile, UnknownKey) {
  json d = default_document();
  d["bladed_disk"]["n_blade"] = 3;
  expect_rejected(d, {"test.json", "bladed_disk.n_blade", "unknown key"});
}

TEST(CaseFile, MissingKey) {
  json d = default_document();
  d["casing"].erase("radius");
  expect_rejected(d, {"casing.radius", "missing"});
}

TEST(CaseFile, WrongType) {
  json d = default_document();
  d["material"]["density"] = "7800";
  expect_rejected(d, {"material.density", "must be a number"});
  d = default_document();
  d["bladed_disk"]["n_blades"] = 22.5;
  expect_rejected(d, {"bladed_disk.n_blades", "integer"});
  d = default_document();
  d["bladed_disk"]["blade_section"] = 0.002;
  expect_rejected(d, {"bladed_disk.blade_section", "JSON object"});
}

TEST(CaseFile, NonPhysicalValues) {
  const std::vector<std::pair<std::vector<std::string>, json>> cases = {
      {{"bladed_disk", "hub_radius"}, -0.1},
      {{"bladed_disk", "blade_section", "thickness"}, 0.0},
      {{"casing", "section", "width"}, -1.0},
      {{"material", "young_modulus"}, 0.0},
      {{"material", "density"}, -7800.0},
      {{"bladed_disk", "n_blades"}, 1},
      {{"casing", "radius"}, 0.5},
      {{"bladed_disk", "rim_radius"}, 0.05},
      {{"operating_point", "friction_coefficient"}, -0.1},
      {{"time", "step"}, 0.0},
      {{"time", "output_every"}, 0},
      {{"casing", "clamp_angle_deg"}, 100.0},
  };
  for (const auto& [path, value] : cases) {
    json d = default_document();
    json* node = &d;
    std::string dotted;
    for (const std::string& key : path) {
      node = &(*node)[key];
      dotted += (dotted.empty() ? "" : ".") + key;
    }
    *node = value;
    expect_rejected(d, {dotted, "must be"});
  }
}

TEST(CaseFile, ClearanceMustBePositive) {
  json d = default_document();
  d["casing"]["radius"] = 0.4999;
  expect_rejected(d, {"casing.radius", "clearance must be positive"});
}

TEST(CaseFile, MalformedAndMissingFiles) {
  EXPECT_THROW(load_case("/nonexistent/case.json"), CaseError);
  const std::string truncated = testing::TempDir() + "/truncated.json";
  {
    std::ofstream out(truncated);
    out << "{\"material\": {\"young_modulus\": 2";
  }
  try {
    load_case(truncated);
    ADD_FAILURE() << "truncated JSON accepted";
  } catch (const CaseError& e) {
    std::printf("rejected: %s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("malformed JSON"), std::string::npos);
  }
}

// Found by fuzz/fuzz_case_loader (fuzz/corpus/crash-number-overflow.json):
// a number beyond the range of a double made nlohmann throw out_of_range,
// not parse_error, which escaped the loader (the CLI exited 1, not 2).
TEST(CaseFile, NumberBeyondDoubleRange) {
  std::string text = default_document().dump();
  const std::string from = "\"young_modulus\":210000000000.0";
  ASSERT_NE(text.find(from), std::string::npos) << text;
  text.replace(text.find(from), from.size(), "\"young_modulus\":210e999");
  try {
    parse_case_text(text, "test.json");
    ADD_FAILURE() << "1e999 accepted";
  } catch (const CaseError& e) {
    std::printf("rejected: %s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("test.json: malformed JSON"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("210e999"), std::string::npos);
  }
}

} // namespace
} // namespace rsi
