// Study columns in words (post/study_words.h): the selectors of configs/studies/ read as an
// engineer would title an axis; an unknown selector falls back to the column's key.
#include <gtest/gtest.h>

#include "post/polar_study.h"
#include "post/study_words.h"

namespace isopound::post {
namespace {

TEST(PostStudyWords, SelectorsOfTheShippedStudiesReadAsWords) {
  const std::pair<const char*, const char*> cases[] = {
      {"base.displacement", "peak base displacement"},
      {"base.corners.displacement", "peak base displacement (largest corner)"},
      {"roof.absolute_acceleration", "peak roof absolute acceleration"},
      {"roof.theta", "peak roof rotation θ"},
      {"stories.drift_ratio", "peak storey drift ratio (largest storey)"},
      {"story2.corners.drift_ratio", "peak storey 2 drift ratio (largest corner column)"},
      {"stories.corners.drift_ratio",
       "peak storey drift ratio (largest corner column of any storey)"},
      {"floors.absolute_acceleration", "peak floor absolute acceleration (largest floor)"},
      {"floors.corners.absolute_acceleration",
       "peak floor absolute acceleration (largest floor corner)"},
      {"wall*.force", "peak wall force (largest wall)"},
      {"bearing*.deformation", "peak bearing deformation (largest bearing)"},
      {"isolator.force", "peak isolator force"},
      {"sum:wall*.impacts", "number of impacts (sum over walls)"},
      {"sum:contacts.impacts", "number of impacts (sum over contacts)"},
      {"contacts.normal_force", "peak contact normal force (largest contact)"},
      {"*~*.force", "peak contact force (largest contact)"},
      {"sum:contacts.friction_dissipated_energy", "friction dissipated energy (sum over contacts)"},
      {"energy.relative_error", "energy balance relative error"},
      {"ground.pga", "PGA"},
  };
  for (const auto& [selector, words] : cases) EXPECT_EQ(output_words(selector), words) << selector;
  EXPECT_EQ(output_words(""), "");
  EXPECT_EQ(output_words("no dot"), "");
}

TEST(PostStudyWords, TitlesCarryTheUnitAndFallBackToTheKey) {
  EXPECT_EQ(output_title("base.displacement", "u_base", "cm"), "peak base displacement [cm]");
  EXPECT_EQ(output_title("stories.drift_ratio", "drift_ratio", "%"),
            "peak storey drift ratio (largest storey) [%]");
  EXPECT_EQ(output_title("", "u_base", "cm"), "peak u_base [cm]");  // the study file is gone
  EXPECT_EQ(output_title("sum:wall*.impacts", "impacts", "-"),
            "number of impacts (sum over walls)");
  EXPECT_EQ(axis_words("angle"), "incidence angle");
  EXPECT_EQ(axis_words("gap"), "gap");
  EXPECT_EQ(axis_words("level_mismatch"), "level mismatch");
  EXPECT_EQ(capitalised("peak base"), "Peak base");
  // Axis units from the names (sweep-plot's x axis and polar's contour radius alike).
  EXPECT_EQ(axis_display_unit("QW").unit, "%");
  EXPECT_EQ(axis_display_unit("gap").unit, "cm");
  EXPECT_EQ(axis_display_unit("angle").unit, "deg");
  EXPECT_EQ(axis_display_unit("mismatch").unit, "SI");
}

}  // namespace
}  // namespace isopound::post
