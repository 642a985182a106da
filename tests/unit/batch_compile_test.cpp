// compileBatch: an exception escaping one graph's compile is that graph's WG9900, and the
// other graphs of the batch still compile.
#include <gtest/gtest.h>

#include <stdexcept>

#include "driver/batch_compile.hpp"

namespace wg {
namespace {

const std::string kRock = std::string(WG_SOURCE_DIR) + "/graphs/rock.json";
const std::string kRoad = std::string(WG_SOURCE_DIR) + "/graphs/road.json";

TEST(BatchCompile, AnExceptionInOneGraphIsItsInternalErrorAndTheOthersCompile) {
  CompileOptions options{.emitSpirv = false};
  options.passes.afterPass = [](const Pass&, const IrGraph& ir) {
    if (ir.name == "road") throw std::runtime_error("a pass broke");
  };
  for (int jobs : {1, 2}) {
    const std::vector<CompileResult> results = compileBatch({kRoad, kRock, kRoad}, options, jobs);
    ASSERT_EQ(results.size(), 3u);
    EXPECT_TRUE(results[1].material) << "rock compiles whatever road does";
    for (std::size_t i : {0u, 2u}) {
      EXPECT_FALSE(results[i].material);
      ASSERT_EQ(results[i].diagnostics.items().size(), 1u);
      const Diagnostic& d = results[i].diagnostics.items().front();
      EXPECT_EQ(d.code, DiagCode::InternalException);
      EXPECT_EQ(d.location.file, kRoad);
      EXPECT_NE(d.message.find("a pass broke"), std::string::npos) << d.message;
    }
  }
}

}  // namespace
}  // namespace wg
