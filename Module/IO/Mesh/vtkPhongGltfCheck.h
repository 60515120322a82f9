/**
 * @class   vtkPhongGltfCheck
 * @brief   refuses glTF and GLB files that would crash assimp, before assimp sees them
 *
 * assimp parses glTF's JSON with a recursive parser and walks the node hierarchy
 * recursively: a 400 KB file nesting its JSON 200 000 levels deep overflows the stack
 * (assimp's own `assimp info` too), and so would a chain of nodes as deep, or a cycle of
 * nodes. In a child process that is a contained crash; in-process (vtkPhongAssimpReader from
 * Python, or in ParaView) it takes the whole program down. These checks read the JSON once,
 * without recursion, before assimp does:
 *
 * - the nesting of arrays and objects, at most MaximumNesting levels;
 * - the nodes' children: each an existing node, no cycle, chains at most MaximumNodeDepth
 *   nodes deep;
 * - a GLB's JSON chunk within the file.
 *
 * Private to vtkPhongAssimpReader.
 */

#ifndef vtkPhongGltfCheck_h
#define vtkPhongGltfCheck_h

#include <string>

class vtkPhongGltfCheck
{
public:
  static constexpr int MaximumNesting = 256;
  static constexpr int MaximumNodeDepth = 1024;

  /**
   * Why the file must not reach assimp, or an empty string (also for files that are not
   * glTF: .gltf by extension, GLB by its magic number).
   */
  static std::string WhyRefused(const std::string& path);

private:
  // The JSON text of the file, or an empty string when it is no glTF; why is set for a
  // GLB whose JSON chunk cannot be.
  static std::string ReadJson(const std::string& path, std::string& why);
  // The deepest nesting of arrays and objects, stopping once past MaximumNesting.
  static int NestingOf(const std::string& json);
  // Why the node hierarchy would overflow a recursive walk, or an empty string.
  static std::string CheckNodes(const std::string& json);
};

#endif
