// xval_model_probe FILE...: loads each model file with loadModelFile and
// prints one line per file:
//   loaded <file>: <P> primitives, <T> triangles, <V> vertices
//   refused <message>            (a ModelFileError: names the file and why)
// Exit status 0 when every file was loaded or refused; 2 when anything
// else escaped the loader (an exception of another type: a loader bug).
// A crash or a hang is seen by the caller (tests/corpus/model_corpus.cpp
// runs one probe per file, with a time-out).
#include <exception>
#include <iostream>

#include "geometry/model_file.h"

int main(int argc, char** argv) {
  int status = 0;
  for (int i = 1; i < argc; ++i) {
    try {
      xval::ModelLoadOptions o;
      o.uvs = xval::UvRequirement::ModelTextures;
      const xval::Model m = xval::loadModelFile(argv[i], o);
      std::cout << "loaded " << argv[i] << ": " << m.primitives.size() << " primitives, " << m.triangleCount()
                << " triangles, " << m.vertexCount() << " vertices\n";
    } catch (const xval::ModelFileError& e) {
      std::cout << "refused " << e.what() << "\n";
    } catch (const std::exception& e) {
      std::cout << "escaped " << argv[i] << ": " << e.what() << "\n";
      status = 2;
    }
  }
  return status;
}
