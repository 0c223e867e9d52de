#pragma once
namespace vem::bench {
void registerStageBenchmarks();
}
