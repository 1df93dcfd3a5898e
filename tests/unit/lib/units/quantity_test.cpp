#include "lib/units/quantity.h"
#include "lib/units/quantity_display.h"

#include <gtest/gtest.h>

#include <limits>

#include "lib/common/input_error.h"
#include "lib/truth/effect.h"
#include "lib/units/units.h"

namespace insmc {
namespace {

struct Case {
  const char* text;
  Dimension dimension;
  double expected_si;
};

TEST(ParseQuantity, AcceptsEveryDocumentedUnit) {
  const Case cases[] = {
      {"15min", Dimension::kTime, 900.0},
      {"900s", Dimension::kTime, 900.0},
      {"1.5h", Dimension::kTime, 5400.0},
      {"10meru", Dimension::kAngularRate, 10e-3 * kEarthRateRadps},
      {"1mg", Dimension::kAcceleration, 1e-3 * 9.80665},
      {"0.3mps", Dimension::kVelocity, 0.3},
      {"0.1ftps", Dimension::kVelocity, 0.03048},
      {"100m", Dimension::kLength, 100.0},
      {"3ft", Dimension::kLength, 0.9144},
      {"1mrad", Dimension::kAngle, 1e-3},
      {"20arcsec", Dimension::kAngle, 20.0 / 3600.0 * kDegToRad},
      {"45deg", Dimension::kAngle, 45.0 * kDegToRad},
      {"100ppm", Dimension::kDimensionless, 1e-4},
      {"1e-4", Dimension::kDimensionless, 1e-4},
      {"-2.5mg", Dimension::kAcceleration, -2.5e-3 * 9.80665},
  };
  for (const Case& c : cases) {
    EXPECT_DOUBLE_EQ(parse_quantity(c.text, c.dimension, "f"), c.expected_si) << c.text;
  }
}

TEST(ParseQuantity, RefusesMissingWrongOrNonFiniteValues) {
  const Case bad[] = {
      {"10", Dimension::kAngularRate, 0},     // unit required
      {"10mg", Dimension::kAngularRate, 0},   // wrong dimension
      {"abc", Dimension::kTime, 0},           // not a number
      {"nanmin", Dimension::kTime, 0},        // NaN
      {"infs", Dimension::kTime, 0},          // infinite
      {"", Dimension::kLength, 0},            // empty
      {"5furlong", Dimension::kLength, 0},    // unknown unit
  };
  for (const Case& c : bad) {
    EXPECT_THROW(parse_quantity(c.text, c.dimension, "field"), InputError) << c.text;
  }
}

TEST(ParseQuantity, TheNumberAndTheUnitAreEachReadWhole) {
  // strtod read hexadecimal and blanks into the number ("0x10s" was 16 s).
  for (const char* text : {"0x10s", " 5s", "\t5s", "5s ", "0s5", "1e", "e3s", ".s", "-s", "+-5s", "5 e3s"})
    EXPECT_THROW(parse_quantity(text, Dimension::kTime, "f"), InputError) << text;
  EXPECT_EQ(parse_quantity("+5s", Dimension::kTime, "f"), 5.0);
  EXPECT_EQ(parse_quantity(".5s", Dimension::kTime, "f"), 0.5);
  EXPECT_EQ(parse_quantity("5.s", Dimension::kTime, "f"), 5.0);
  EXPECT_EQ(parse_quantity("1e3s", Dimension::kTime, "f"), 1000.0);
  EXPECT_EQ(parse_quantity("2E-3 s", Dimension::kTime, "f"), 2e-3);
  EXPECT_THROW(parse_quantity("1e999s", Dimension::kTime, "f"), InputError);
  const auto q = split_quantity("-2.5e1mg");
  ASSERT_TRUE(q);
  EXPECT_EQ(q->number, -25.0);
  EXPECT_EQ(q->unit, "mg");
  EXPECT_FALSE(split_quantity("mg"));
  // A unit alone: no number is read out of it.
  EXPECT_EQ(unit_factor("min", Dimension::kTime), 60.0);
  EXPECT_EQ(unit_factor("hr", Dimension::kTime), 3600.0);
  for (const char* unit : {"0s", ".5s", "e3s", "1s", " s", "", "mg"})
    EXPECT_FALSE(unit_factor(unit, Dimension::kTime)) << unit;
}

TEST(ParseQuantity, ErrorNamesFieldValueAndAcceptedUnits) {
  try {
    parse_quantity("10", Dimension::kAngularRate, "gyro_drift_x");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("gyro_drift_x = 10"), std::string::npos) << msg;
    EXPECT_NE(msg.find("meru"), std::string::npos) << msg;
  }
}

TEST(FormatQuantity, ReportsRoundToTheFiguresAsked) {
  EXPECT_EQ(format_quantity_rounded(4.49740608052e-3 * kGravityMps2, Dimension::kAcceleration), "4.5mg");
  EXPECT_EQ(format_quantity_rounded(3.16227766017 * kMeruToRadps, Dimension::kAngularRate), "3.16meru");
  EXPECT_EQ(format_quantity_rounded(3.16227766017 * kMeruToRadps, Dimension::kAngularRate, 5), "3.1623meru");
  // A report's value still parses back to itself at that precision.
  EXPECT_NEAR(parse_quantity(format_quantity_rounded(0.123456, Dimension::kTime), Dimension::kTime, "f"), 0.123, 1e-12);
}

TEST(FormatQuantity, RoundTripsThroughParse) {
  const double values[] = {0.0, 1e-12, 7.292115e-8, 1.0, -3.5};
  const Dimension dims[] = {Dimension::kAngularRate, Dimension::kAcceleration, Dimension::kAngle,
                            Dimension::kTime, Dimension::kDimensionless};
  for (Dimension d : dims) {
    for (double v : values) {
      const std::string text = format_quantity(v, d);
      EXPECT_NEAR(parse_quantity(text, d, "f"), v, 1e-11 * std::abs(v) + 1e-300) << text;
    }
  }
}

TEST(Constants, SchulerPeriodIs84Point4Minutes) {
  const double period_min = 2 * std::numbers::pi / schuler_frequency_radps() / 60.0;
  EXPECT_NEAR(period_min, 84.4, 0.05);
  EXPECT_DOUBLE_EQ(kEarthRadiusM, 20.9e6 * 0.3048);
}

}  // namespace
}  // namespace insmc

namespace insmc {
namespace {

TEST(SensorSpecUnits, RandomWalksPerRootHourAndSecond) {
  // 1/√h = 1/60 · 1/√s.
  EXPECT_DOUBLE_EQ(parse_quantity("0.005degprth", Dimension::kAngleRandomWalk, "f"), 0.005 * kDegToRad / 60);
  EXPECT_DOUBLE_EQ(parse_quantity("0.03mpsprth", Dimension::kVelocityRandomWalk, "f"), 0.03 / 60);
  EXPECT_DOUBLE_EQ(parse_quantity("2e-5radprts", Dimension::kAngleRandomWalk, "f"), 2e-5);
  EXPECT_THROW(parse_quantity("0.005deg", Dimension::kAngleRandomWalk, "f"), InputError);
  EXPECT_THROW(parse_quantity("0.005degprth", Dimension::kAngle, "f"), InputError);
}

TEST(SensorSpecUnits, EffectsTakeTheWalkForTheirValueAfterOneHour) {
  const EffectSpec by_angle = parse_effect("angle_random_walk:angle_1h=0.005deg");
  const EffectSpec by_walk = parse_effect("angle_random_walk:angle_1h=0.005degprth");
  EXPECT_NEAR(by_walk.values_si[0], by_angle.values_si[0], 1e-15);
  const EffectSpec v = parse_effect("velocity_random_walk:velocity_1h=0.03mpsprth");
  EXPECT_NEAR(v.values_si[0], 0.03, 1e-12);
  // Every spelling of the walk's unit (README.md), not only the suffixes.
  for (const char* spelled : {"0.03m/s/√h", "0.03m/s/sqrt(h)"})
    EXPECT_EQ(parse_effect(std::string("velocity_random_walk:velocity_1h=") + spelled).values_si[0], v.values_si[0])
        << spelled;
  EXPECT_EQ(parse_effect("angle_random_walk:angle_1h=0.005deg/√h").values_si[0], by_walk.values_si[0]);
}

TEST(UnitSpellings, TheUsualSpellingsOfDataSheetsAndThePaperAreTheirUnits) {
  // Each spelling against its table unit, so a slip in the table shows.
  const struct {
    const char* typed;
    const char* unit;
    Dimension d;
  } cases[] = {{"3deg/h", "3degph", Dimension::kAngularRate},   {"3 deg/hr", "3degph", Dimension::kAngularRate},
               {"3°/h", "3degph", Dimension::kAngularRate},     {"0.2dph", "0.2degph", Dimension::kAngularRate},
               {"5µg", "5ug", Dimension::kAcceleration},        {"5μg", "5ug", Dimension::kAcceleration},
               {"2m/s²", "2mps2", Dimension::kAcceleration},    {"2m/s^2", "2mps2", Dimension::kAcceleration},
               {"0.1ft/s", "0.1ftps", Dimension::kVelocity},    {"0.3m/s", "0.3mps", Dimension::kVelocity},
               {"1.5NM", "1.5nmi", Dimension::kLength},         {"1.5n.mi.", "1.5nmi", Dimension::kLength},
               {"20µrad", "20urad", Dimension::kAngle},         {"1°", "1deg", Dimension::kAngle},
               {"2hr", "2h", Dimension::kTime},                 {"0.1deg/sqrt(h)", "0.1degprth", Dimension::kAngleRandomWalk},
               {"0.03m/s/√h", "0.03mpsprth", Dimension::kVelocityRandomWalk}};
  for (const auto& c : cases)
    EXPECT_EQ(parse_quantity(c.typed, c.d, "f"), parse_quantity(c.unit, c.d, "f")) << c.typed;
  // A spelling of another dimension is still refused.
  EXPECT_THROW(parse_quantity("3deg/h", Dimension::kAcceleration, "f"), InputError);
  EXPECT_THROW(parse_quantity("5µg", Dimension::kAngularRate, "f"), InputError);
  // The refusal lists the spellings of that dimension only.
  try {
    parse_quantity("3deg/h", Dimension::kAcceleration, "f");
  } catch (const InputError& e) {
    const std::string m = e.what();
    const std::string listed = m.substr(m.find("expected"));
    EXPECT_NE(listed.find("µg"), std::string::npos) << m;
    EXPECT_EQ(listed.find("deg/h"), std::string::npos) << "a rate's spelling listed for an acceleration: " << m;
  }
}

}  // namespace
}  // namespace insmc
