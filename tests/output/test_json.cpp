// Json: RFC 8259 string escaping, insertion-ordered objects, exact integers, round-tripping
// doubles, null for non-finite numbers, and the atomic file write.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

#include "output/json.hpp"

namespace fs = std::filesystem;
using plyimpact::output::Json;

TEST(Json, EscapesQuotesBackslashAndControlCharacters) {
  EXPECT_EQ(Json("say \"hi\"").dump(), R"("say \"hi\"")");
  EXPECT_EQ(Json("C:\\dir").dump(), R"("C:\\dir")");
  EXPECT_EQ(Json("a\nb\tc\rd\be\ff").dump(), R"("a\nb\tc\rd\be\ff")");
  EXPECT_EQ(Json(std::string("x\x01y\x1fz", 5)).dump(), R"("x\u0001y\u001fz")");
  EXPECT_EQ(Json(std::string("nul\0end", 7)).dump(), R"("nul\u0000end")");
  EXPECT_EQ(Json("/ and \x7f stay").dump(), "\"/ and \x7f stay\"");
}

TEST(Json, PassesUtf8Through) {
  const std::string text = "\xC3\xA9prouvette 0\xC2\xB0 \xE2\x80\x94 \xF0\x9F\x92\xA5";  // é ° — 💥
  EXPECT_EQ(Json(text).dump(), "\"" + text + "\"");
}

TEST(Json, NestedObjectsKeepInsertionOrder) {
  Json summary;
  summary["name"] = "plate";
  summary["steps"] = 10;
  Json& run = summary["run"];
  run["converged"] = true;
  run["times"].push_back(0.0);
  run["times"].push_back(0.5);
  run["times"].push_back(Json::object());
  summary["empty"] = Json::array();
  summary["nothing"] = nullptr;
  summary["steps"] = 11;  // replacing keeps the original position

  EXPECT_EQ(summary.kind(), Json::Kind::object);
  EXPECT_EQ(summary.size(), 5u);
  ASSERT_NE(summary.find("run"), nullptr);
  EXPECT_EQ(summary.find("run")->find("times")->size(), 3u);
  EXPECT_EQ(summary.find("missing"), nullptr);

  EXPECT_EQ(summary.dump(),
            "{\n"
            "  \"name\": \"plate\",\n"
            "  \"steps\": 11,\n"
            "  \"run\": {\n"
            "    \"converged\": true,\n"
            "    \"times\": [\n"
            "      0.0,\n"
            "      0.5,\n"
            "      {}\n"
            "    ]\n"
            "  },\n"
            "  \"empty\": [],\n"
            "  \"nothing\": null\n"
            "}");
  EXPECT_EQ(summary.dump(0),
            R"({"name":"plate","steps":11,"run":{"converged":true,"times":[0.0,0.5,{}]},)"
            R"("empty":[],"nothing":null})");
}

TEST(Json, NonFiniteDoublesAreNull) {
  EXPECT_EQ(Json(std::numeric_limits<double>::quiet_NaN()).dump(), "null");
  EXPECT_EQ(Json(std::numeric_limits<double>::infinity()).dump(), "null");
  EXPECT_EQ(Json(-std::numeric_limits<double>::infinity()).dump(), "null");
  Json a;
  a.push_back(1.5);
  a.push_back(std::nan(""));
  EXPECT_EQ(a.dump(0), "[1.5,null]");
}

TEST(Json, IntegersAreExact) {
  const std::int64_t max_safe = (std::int64_t{1} << 53) - 1;
  EXPECT_EQ(Json(max_safe).dump(), "9007199254740991");
  EXPECT_EQ(Json(max_safe + 2).dump(), "9007199254740993");  // not representable as a double
  EXPECT_EQ(Json(std::numeric_limits<std::int64_t>::min()).dump(), "-9223372036854775808");
  EXPECT_EQ(Json(std::numeric_limits<std::uint64_t>::max()).dump(), "18446744073709551615");
  EXPECT_EQ(Json(0).dump(), "0");
  EXPECT_EQ(Json(-42L).dump(), "-42");
  EXPECT_EQ(Json(max_safe).kind(), Json::Kind::integer);
}

TEST(Json, DoublesRoundTripInAtMost17SignificantDigits) {
  for (const double v : {0.1, 1.0 / 3.0, -2.5e-7, 1e-300, 5e-324, DBL_MAX, 6.02214076e23,
                         123456789.123456789, 1e21}) {
    const std::string text = Json(v).dump();
    SCOPED_TRACE(text);
    EXPECT_EQ(std::strtod(text.c_str(), nullptr), v);
    std::size_t digits = 0;
    for (const char c : text.substr(0, text.find_first_of("eE"))) digits += (c >= '0' && c <= '9');
    EXPECT_LE(digits, 17u);
  }
  EXPECT_EQ(Json(0.1).dump(), "0.1");      // trimmed, not 0.10000000000000001
  EXPECT_EQ(Json(2.0).dump(), "2.0");      // stays recognisably a double
  EXPECT_EQ(Json(-0.0).dump(), "-0.0");
  EXPECT_EQ(Json(2.0f).kind(), Json::Kind::number);
}

TEST(Json, WrongKindAccessIsALogicError) {
  Json s = "text";
  EXPECT_THROW(s.push_back(1), std::logic_error);
  EXPECT_THROW(s["key"], std::logic_error);
  EXPECT_THROW(Json::array().at(0), std::out_of_range);
  EXPECT_EQ(Json(false).dump(), "false");
}

TEST(Json, WritesFileAtomically) {
  const fs::path dir = fs::temp_directory_path() /
                       ("plyimpact_output_json_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  Json summary;
  summary["wall_time_s"] = 1.25;
  plyimpact::output::write_json_atomically(dir / "summary.json", summary);
  std::ifstream in(dir / "summary.json");
  std::stringstream content;
  content << in.rdbuf();
  EXPECT_EQ(content.str(), summary.dump() + "\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  fs::remove_all(dir);
}
