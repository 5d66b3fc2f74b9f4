#include "common/hostile_cases.hpp"
TEST(HostileCpu, PeersReportedFailures) { gdel::test::hostile_cases(gdel::Backend::Cpu); }
