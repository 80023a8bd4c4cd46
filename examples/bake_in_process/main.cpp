// Bakes E and dfg in-process with lutbake's library and prints each file's
// bound as stored. Usage: bake_in_process OUTPUT_DIRECTORY
#include <lutbake/lutbake.h>

#include <iostream>

int main(int argc, char **argv) {
  if (argc != 2) {
    std::cerr << "usage: bake_in_process OUTPUT_DIRECTORY\n";
    return 2;
  }
  lutbake::BakeRequest request;
  request.tables = {"E", "dfg"};
  request.formats = {"exr", "header"};
  request.outputDirectory = argv[1];
  try {
    const lutbake::BakeResult result = lutbake::Bake(request);  // all files, or none
    for (const lutbake::WrittenFile &f : result.files)
      std::cout << f.path << ' ' << f.errorMax << '\n';  // 0: no values (lutbake-set.json)
  } catch (const lutbake::Error &e) {
    std::cerr << "bake_in_process: " << e.what() << '\n';
    return e.kind() == lutbake::Error::Kind::kUsage ? 2 : 1;
  }
  return 0;
}
