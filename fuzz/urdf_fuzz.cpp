// libFuzzer harness for the URDF reader: a body model or an InputError, nothing else.
#include <cstddef>
#include <cstdint>
#include <string>

#include "body/urdf_loader.hpp"
#include "common/input_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    crux::load_body_model_from_string(std::string(reinterpret_cast<const char*>(data), size), "fuzz.urdf");
  } catch (const crux::InputError&) {
  }
  return 0;
}
