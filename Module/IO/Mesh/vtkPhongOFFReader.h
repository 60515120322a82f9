/**
 * @class   vtkPhongOFFReader
 * @brief   reads Object File Format (.off) meshes into vtkPolyData
 *
 * VTK 9.1 has no reader for the ASCII OFF format in which CGAL, Geomview and many mesh
 * collections ship their data. vtkPhongOFFReader reads its common variants:
 *
 * - "OFF" (positions), "COFF" (a colour per vertex), "NOFF" (a normal per vertex),
 *   "CNOFF" and "NCOFF" (both), with the keyword alone on its line or followed by the counts;
 * - faces of any size (polygons) and an optional colour after a face's indices;
 * - '#' comments, blank lines and Windows line endings anywhere.
 *
 * Vertex colours become unsigned-char RGBA point scalars named "Colors", face colours cell
 * scalars of the same name, vertex normals the point normals. Colour components written as
 * integers are read in [0, 255], those written with a decimal point in [0, 1].
 *
 * A file that is not OFF, is binary OFF, or is truncated or refers to vertices that do not
 * exist is reported with vtkErrorMacro naming the line, and gives an empty output; faces with
 * fewer than three vertices are skipped with a warning giving their count.
 *
 * @sa vtkPolyDataReader
 */

#ifndef vtkPhongOFFReader_h
#define vtkPhongOFFReader_h

#include "vtkIOMeshModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <string> // for std::string

class VTKIOMESH_EXPORT vtkPhongOFFReader : public vtkPolyDataAlgorithm
{
public:
  static vtkPhongOFFReader* New();
  vtkTypeMacro(vtkPhongOFFReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The file to read. Default none.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  /**
   * Whether the file starts like an OFF file (its first keyword ends in "OFF").
   */
  static bool CanReadFile(const char* fileName);

  ///@{
  /**
   * Faces skipped while reading the last file because they had fewer than three vertices.
   */
  vtkGetMacro(NumberOfSkippedFaces, vtkIdType);
  ///@}

protected:
  vtkPhongOFFReader();
  ~vtkPhongOFFReader() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;
  vtkIdType NumberOfSkippedFaces = 0;

private:
  vtkPhongOFFReader(const vtkPhongOFFReader&) = delete;
  void operator=(const vtkPhongOFFReader&) = delete;
};

#endif
