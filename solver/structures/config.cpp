// Out-of-line special members of ModelConfig: its 3D structures (Building3DConfig) are complete
// only here and where config3d.h is included (config.h only forward-declares them).
#include "solver/structures/config.h"

#include "solver/structures/config3d.h"

namespace isopound {

ModelConfig::ModelConfig() = default;
ModelConfig::~ModelConfig() = default;
ModelConfig::ModelConfig(const ModelConfig&) = default;
ModelConfig::ModelConfig(ModelConfig&&) noexcept = default;
ModelConfig& ModelConfig::operator=(const ModelConfig&) = default;
ModelConfig& ModelConfig::operator=(ModelConfig&&) noexcept = default;

}  // namespace isopound
