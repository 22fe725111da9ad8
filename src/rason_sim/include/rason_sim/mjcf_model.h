// Compiling an MJCF document held in memory (MuJoCo 2.2 loads only files: it goes through
// MuJoCo's virtual file system).
#pragma once

#include <mujoco/mujoco.h>

#include <string>

namespace rason_sim {

// The compiled model (free it with mj_deleteModel); throws std::runtime_error with
// MuJoCo's message when it rejects the document.
mjModel* compileMjcf(const std::string& xml);

}  // namespace rason_sim
