#include "io/input_frame.h"

#include "io/pcd_input.h"

namespace floodplane::io {

InputFrame loadInputFrame(const std::string& path) {
  // PCD is the only kind so far, whatever the file's extension: the PCD reader's own checks
  // say what is wrong with a file that is not one. A second kind adds its test here.
  return readPcdFrame(path);
}

}  // namespace floodplane::io
