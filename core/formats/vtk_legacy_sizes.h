#pragma once
// The sizes a VTK legacy file (.vtk) declares, checked against the file's size before VTK reads
// it. VTK 9.1's legacy reader allocates each array at the size its keyword line declares before
// it reads a value, and goes on when the allocation fails: with a failed allocation it reads and
// byte-swaps through a null pointer (SEGV in vtkByteSwap::SwapBERange under
// vtkDataReader::ReadCells, found by CI's fuzzing smoke in a binary file whose cell count had
// grown), and the arrays of the failed read leak.
//
// An array's values must fit in the file: in a binary file each value takes its type's size
// (a bit an eighth of a byte, a string at least one byte), in an ASCII file at least one byte. A
// declared size past that, or a negative one, is refused with the line and the keyword. The
// declarations read are those VTK allocates by:
//   POINTS n type; VERTICES, LINES, POLYGONS, TRIANGLE_STRIPS, CELLS a b (version 5: a offsets,
//   b connectivity values of the types on the OFFSETS and CONNECTIVITY lines; before: b ints);
//   CELL_TYPES n; X_, Y_, Z_COORDINATES n type; POINT_DATA and CELL_DATA n, the count of each
//   attribute after them: SCALARS name type [components], COLOR_SCALARS name components,
//   VECTORS and NORMALS (3), TEXTURE_COORDINATES name dimension type, TENSORS (9), TENSORS6
//   (6), GLOBAL_IDS and PEDIGREE_IDS (1); LOOKUP_TABLE name size (4 per entry); FIELD name n
//   and its arrays' "name components tuples type" lines.
// An unstructured grid's CELL_TYPES must declare a type for each cell of its CELLS list (VTK
// 9.1 reads a type for each cell, past the ones the file gives).
// A cell list before version 5 (each cell its point count, then its points; also a file whose
// version line VTK cannot read, which it reads as version 0.0) is read and walked: a cell whose
// count runs past the list, counts that do not make as many cells as declared, a list cut short
// and a value that is no whole number are refused (VTK 9.1 appends cells until the list's end by
// the counts it holds, unchecked).
// The dataset section of a version 5 file (up to its POINT_DATA or CELL_DATA; polygonal data,
// unstructured, structured and rectilinear grids, structured points) is then walked token by
// token as VTK walks it: a FIELD block must read (its header; each array's name, components,
// tuples and a type VTK knows), and each ASCII value of its points, cell lists, cell types,
// coordinates and field arrays must read whole as a number. VTK 9.1's readers delete the null
// field data of a FIELD block they failed to read there (SEGV), and its
// ASCII readers go on after a value that does not read ("1field" read as 1, then a FIELD
// keyword).
// The file is scanned line by line for these keywords at the start of a line (as VTK's writer
// puts them), case-insensitively as VTK reads them; lines of binary data that do not parse as a
// declaration are passed over. What the check cannot read is left to VTK's reader.
#include <optional>
#include <string>

namespace aniso
{
// Why the file's declared sizes are refused ("line 12: POLYGONS declares 9999999999 offsets of
// 8 bytes, more than the file's 2 236 bytes hold"), or nothing when they fit. Throws
// aniso::Error naming the file when it cannot be opened.
std::optional<std::string> vtkLegacySizeProblem(const std::string& path);

// Throws aniso::Error "PATH: reason" when vtkLegacySizeProblem finds one.
void checkVtkLegacySizes(const std::string& path);
} // namespace aniso
