#include "rason_sim/mjcf_model.h"

#include <cstring>
#include <memory>
#include <stdexcept>

namespace rason_sim {

mjModel* compileMjcf(const std::string& xml) {
  std::unique_ptr<mjVFS> vfs(new mjVFS);
  mj_defaultVFS(vfs.get());
  const char* file = "rason_world.xml";
  if (mj_makeEmptyFileVFS(vfs.get(), file, static_cast<int>(xml.size())) != 0)
    throw std::runtime_error("MuJoCo VFS is full");
  const int index = mj_findFileVFS(vfs.get(), file);
  std::memcpy(vfs->filedata[index], xml.data(), xml.size());
  char error[1000] = "";
  mjModel* model = mj_loadXML(file, vfs.get(), error, sizeof(error));
  mj_deleteVFS(vfs.get());
  if (!model) throw std::runtime_error(std::string("MuJoCo rejected the world: ") + error);
  return model;
}

}  // namespace rason_sim
