// Strict JSON reader: what the writer produces reads back to the same tree (types included), the
// RFC 8259 escapes and number grammar are honoured, and every deviation is refused with line:col.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "output/json.hpp"
#include "output/json_reader.hpp"

namespace plyimpact {
namespace {

using output::Json;
using output::parse_json;

TEST(JsonReader, ReadsBackWhatTheWriterWrites) {
  Json j = Json::object();
  j["scene"] = "bar \"wave\"\n\t\\";
  j["cycles"] = 1234567890123;
  j["time"] = 1.5e-5;
  j["ratio"] = 0.1 + 0.2;  // needs 17 digits
  j["ok"] = true;
  j["none"] = nullptr;
  j["list"] = Json(Json::Array{1, 2.5, "x"});
  j["nested"]["deep"]["n"] = -7;
  for (int indent : {0, 2}) {
    const Json r = parse_json(j.dump(indent), "written");
    EXPECT_EQ(r.dump(2), j.dump(2));
    EXPECT_EQ(r.find("cycles")->kind(), Json::Kind::integer);
    EXPECT_EQ(r.find("time")->kind(), Json::Kind::number);
    EXPECT_EQ(r.find("ratio")->as_number(), 0.1 + 0.2);  // bit-exact round trip
    EXPECT_EQ(r.find("scene")->as_string(), "bar \"wave\"\n\t\\");
  }
}

TEST(JsonReader, EscapesAndNumbers) {
  const Json r = parse_json(R"({"u": "\u00e9\ud83d\ude00\/", "big": 18446744073709551615, "neg": -0, "e": 1E+2})", "t");
  EXPECT_EQ(r.find("u")->as_string(), "\xc3\xa9\xf0\x9f\x98\x80/");
  EXPECT_EQ(r.find("big")->kind(), Json::Kind::integer);
  EXPECT_EQ(r.find("big")->as_number(), 18446744073709551615.0);
  EXPECT_EQ(r.find("e")->as_number(), 100.0);
}

TEST(JsonReader, RefusesWhatIsNotStrictJson) {
  const char* bad[] = {"{\"a\": 1,}",   "[1, 2,]",        "{'a': 1}",      "{\"a\": 01}",   "{\"a\": NaN}",
                       "{\"a\": 1} x", "{\"a\": 1, \"a\": 2}", "\"tab\there\"", "// c\n{}",   "{\"a\": .5}",
                       "[\"\\x\"]",    "\"\\ud800\"",     "",              "{\"a\" 1}",     "[1e999]"};
  for (const char* text : bad) EXPECT_THROW(parse_json(text, "bad"), InputError) << text;
  try {
    parse_json("{\n  \"a\": 1,\n  \"b\": tru\n}", "summary.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("summary.json:3:8:"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace plyimpact
