#include "vtkPhongGltfCheck.h"

#include "vtk_jsoncpp.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <memory>
#include <sstream>
#include <utility>
#include <vector>

namespace
{
uint32_t LittleEndian32(const unsigned char* bytes)
{
  return uint32_t(bytes[0]) | uint32_t(bytes[1]) << 8 | uint32_t(bytes[2]) << 16 |
    uint32_t(bytes[3]) << 24;
}
}

//------------------------------------------------------------------------------
std::string vtkPhongGltfCheck::WhyRefused(const std::string& path)
{
  std::string why;
  const std::string json = vtkPhongGltfCheck::ReadJson(path, why);
  if (!why.empty() || json.empty())
  {
    return why;
  }
  if (vtkPhongGltfCheck::NestingOf(json) > MaximumNesting)
  {
    return "its JSON nests arrays and objects more than " + std::to_string(MaximumNesting) +
      " levels deep (assimp's recursive parser would overflow the stack).";
  }
  return vtkPhongGltfCheck::CheckNodes(json);
}

//------------------------------------------------------------------------------
std::string vtkPhongGltfCheck::ReadJson(const std::string& path, std::string& why)
{
  std::ifstream file(path, std::ios::binary);
  unsigned char header[20] = {};
  file.read(reinterpret_cast<char*>(header), sizeof(header));
  const std::streamsize got = file.gcount();
  const bool glb =
    got >= 4 && header[0] == 'g' && header[1] == 'l' && header[2] == 'T' && header[3] == 'F';
  const std::string extension =
    vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(path));
  if (!glb && extension != ".gltf")
  {
    return std::string();
  }
  const uint64_t size = vtksys::SystemTools::FileLength(path);
  if (!glb)
  {
    std::ostringstream text;
    file.seekg(0);
    text << file.rdbuf();
    return text.str();
  }
  // GLB: magic, version, length; then the first chunk's length and type ("JSON").
  if (got < 20 || LittleEndian32(header + 16) != 0x4E4F534Au)
  {
    why = "it is a GLB file without a JSON chunk first.";
    return std::string();
  }
  const uint64_t length = LittleEndian32(header + 12);
  if (length > size - 20)
  {
    why = "its JSON chunk announces " + std::to_string(length) + " bytes; the file has " +
      std::to_string(size) + ".";
    return std::string();
  }
  std::string json(static_cast<size_t>(length), '\0');
  file.read(&json[0], static_cast<std::streamsize>(length));
  return json;
}

//------------------------------------------------------------------------------
int vtkPhongGltfCheck::NestingOf(const std::string& json)
{
  int depth = 0, deepest = 0;
  bool inString = false;
  for (size_t i = 0; i < json.size() && deepest <= MaximumNesting; ++i)
  {
    const char c = json[i];
    if (inString)
    {
      i += c == '\\' ? 1 : 0; // the escaped character cannot end the string
      inString = c != '"';
    }
    else if (c == '"')
    {
      inString = true;
    }
    else if (c == '[' || c == '{')
    {
      deepest = std::max(deepest, ++depth);
    }
    else if ((c == ']' || c == '}') && depth > 0)
    {
      --depth;
    }
  }
  return deepest;
}

//------------------------------------------------------------------------------
std::string vtkPhongGltfCheck::CheckNodes(const std::string& json)
{
  Json::CharReaderBuilder builder;
  builder["collectComments"] = false;
  builder["stackLimit"] = MaximumNesting + 8;
  std::unique_ptr<Json::CharReader> reader(builder.newCharReader());
  Json::Value root;
  std::string errors;
  // JSON that jsoncpp does not parse is left to assimp, whose parser decides.
  if (!reader->parse(json.data(), json.data() + json.size(), &root, &errors) || !root.isObject() ||
    !root["nodes"].isArray())
  {
    return std::string();
  }
  const Json::Value& nodes = root["nodes"];
  const Json::ArrayIndex count = nodes.size();
  std::vector<std::vector<Json::ArrayIndex>> children(count);
  std::vector<char> isChild(count, 0);
  for (Json::ArrayIndex n = 0; n < count; ++n)
  {
    const Json::Value& list = nodes[n].isObject() ? nodes[n]["children"] : Json::Value();
    for (Json::ArrayIndex k = 0; list.isArray() && k < list.size(); ++k)
    {
      if (!list[k].isUInt() || list[k].asUInt() >= count)
      {
        return "its node " + std::to_string(n) + " names a child that is not one of its " +
          std::to_string(count) + " nodes.";
      }
      children[n].push_back(list[k].asUInt());
      isChild[list[k].asUInt()] = 1;
    }
  }
  // Depth-first from every node, without recursion: 0 unseen, 1 on the path, 2 done.
  std::vector<char> state(count, 0);
  std::vector<std::pair<Json::ArrayIndex, size_t>> path;
  for (Json::ArrayIndex start = 0; start < count; ++start)
  {
    if (state[start] != 0)
    {
      continue;
    }
    path.emplace_back(start, 0);
    state[start] = 1;
    while (!path.empty())
    {
      auto& top = path.back();
      if (top.second == children[top.first].size())
      {
        state[top.first] = 2;
        path.pop_back();
        continue;
      }
      const Json::ArrayIndex next = children[top.first][top.second++];
      if (state[next] == 1)
      {
        return "its nodes form a cycle (node " + std::to_string(next) + " is its own ancestor).";
      }
      if (state[next] == 0)
      {
        if (path.size() >= static_cast<size_t>(MaximumNodeDepth))
        {
          return "its nodes nest more than " + std::to_string(MaximumNodeDepth) +
            " levels deep (assimp walks them recursively).";
        }
        state[next] = 1;
        path.emplace_back(next, 0);
      }
    }
  }
  return std::string();
}
