// The Catch2 main of every test executable, run as with --warn NoTests: a test spec that matches no
// test case (a ctest entry whose filter lost its test, a mistyped "[tag]") exits 2 instead of
// printing "No tests ran" and passing.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

int main(int argc, char* argv[]) {
  Catch::Session session;
  if (const int status = session.applyCommandLine(argc, argv); status != 0) return status;
  Catch::ConfigData& config = session.configData();
  config.warnings =
      static_cast<Catch::WarnAbout::What>(config.warnings | Catch::WarnAbout::NoTests);
  return session.run();
}
