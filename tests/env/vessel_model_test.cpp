// Cybership II model against the reference numbers of reference-simulator 3.4.
#include "env/vessel_model.h"

#include <gtest/gtest.h>

namespace colav {
namespace {

VesselState Rest() { return VesselState::Zero(); }

TEST(VesselModel, OneStepFromRestFullThrust) {
  const VesselState s = CybershipModel::Step(Rest(), GeneralisedForce(2.0, 0.0, 0.0), 1.0);
  EXPECT_NEAR(s[0], 0.0383701324, 1e-10);
  EXPECT_NEAR(s[3], 0.0763186134, 1e-10);
  EXPECT_DOUBLE_EQ(s[1], 0.0);
  EXPECT_DOUBLE_EQ(s[2], 0.0);
  EXPECT_DOUBLE_EQ(s[4], 0.0);
  EXPECT_DOUBLE_EQ(s[5], 0.0);
}

TEST(VesselModel, OneStepFromRestThrustAndMoment) {
  const VesselState s = CybershipModel::Step(Rest(), GeneralisedForce(2.0, 0.0, 0.15), 1.0);
  const double expected[6] = {0.038381089,  -0.000554010205, 0.0258611986,
                              0.0763184866, -0.00251264992,  0.0500979542};
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(s[k], expected[k], 1e-9) << "component " << k;
}

TEST(VesselModel, OneStepFromMovingState) {
  VesselState s0;
  s0 << 10, -5, 2.5, 0.4, -0.05, 0.03;
  const VesselState s = CybershipModel::Step(s0, GeneralisedForce(1.0, 0.0, -0.075), 1.0);
  const double expected[6] = {9.70557948,  -4.7219718,    2.51027839,
                              0.403929597, -0.0479397239, -0.00793515753};
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(s[k], expected[k], 1e-8) << "component " << k;
}

VesselState SteadyState(const GeneralisedForce& tau) {
  VesselState s = Rest();
  for (int step = 0; step < 3000; ++step) s = CybershipModel::Step(s, tau, 1.0);
  return s;
}

TEST(VesselModel, SteadySpeeds) {
  EXPECT_NEAR(SteadyState(GeneralisedForce(2.0, 0.0, 0.0))[3], 0.578752, 1e-6);
  const VesselState turning = SteadyState(GeneralisedForce(2.0, 0.0, 0.15));
  EXPECT_NEAR(turning[3], 0.5587, 1e-4);
  EXPECT_NEAR(turning[4], -0.1276, 1e-4);
  EXPECT_NEAR(turning[5], 0.04898, 1e-5);
  EXPECT_NEAR(SteadyState(GeneralisedForce(0.0, 0.0, 0.15))[5], 0.293, 1e-3);
}

TEST(VesselModel, ActionMapping) {
  EXPECT_EQ(CybershipModel::ForceFromAction(-1.0, 0.0), GeneralisedForce(0.0, 0.0, 0.0));
  EXPECT_EQ(CybershipModel::ForceFromAction(1.0, 1.0), GeneralisedForce(2.0, 0.0, 0.15));
  EXPECT_EQ(CybershipModel::ForceFromAction(5.0, -7.0), GeneralisedForce(2.0, 0.0, -0.15));
  EXPECT_EQ(CybershipModel::ForceFromAction(0.0, std::nan("")), GeneralisedForce::Zero());
}

}  // namespace
}  // namespace colav
