/**
 * @class   vtkMLAAAreaTexture
 * @brief   The precomputed area texture of morphological antialiasing (the one generator).
 *
 * The blending-weights pass of MLAA (Jimenez et al., "Practical Morphological Antialiasing",
 * GPU Pro 2, section 4.3.3 and Figure 4.2) needs, for each edgel, the area that the revectorised
 * line cuts from the pixel on each side of the edge. That area depends on four numbers only:
 * the crossing-edge codes e1 and e2 at the two ends of the line and the distances `left` and
 * `right` from the pixel to those ends. This class tabulates it.
 *
 * Layout (Figure 4.2): a square of 5 x 5 cells of D x D texels, D = MaxDistance + 1. The cell is
 * chosen by the codes e1, e2 in {0, 1, 3, 4} (code 2 cannot occur; its row and column of cells
 * are zero), and the texel (s, t) = (D * e1 + left, D * e2 + right) holds two areas:
 * - channel 0 (red): the area of the pixel that owns the edgel (the pixel below a horizontal
 *   edge, right of a vertical one), i.e. how much it takes of the colour across the edge;
 * - channel 1 (green): the same for the pixel on the other side of the edge.
 *
 * Crossing-edge codes (section 4.3.2): the crossing edge at an end of the line is read between
 * the pixel's own row (or column) and the opposite one, weighted 3:1, and multiplied by 4:
 * 0 = no crossing edge, 1 = crossing edge on the opposite pixel's side only, 3 = on the owning
 * pixel's side only, 4 = on both sides.
 *
 * The revectorised line (section 4.1): an end with a crossing edge on one side only starts half a
 * pixel into that side, in the middle of the crossing edge, and the line reaches the edge itself
 * at the middle of its length, L / 2 with L = left + right + 1. Two such ends give a U shape
 * (same side) or a Z shape (opposite sides, a straight line through the middle); one gives an
 * L shape. An end with no crossing edge adds nothing. An end with crossing edges on both sides
 * (code 4) is where a one-pixel-wide line (or gap) steps on diagonally: with a one-sided
 * crossing edge at the other end, it acts as a crossing edge on the side opposite to that one,
 * which makes the pattern the Z that the outline of such a line is; with nothing or code 4 at the
 * other end (a + junction, the end of a thin line) no slope can be told and it adds nothing. The
 * chapter leaves code 4's areas to its web material; this reading is the project's. The areas
 * are exact integrals of this piecewise-linear line over the pixel, evaluated in double
 * precision; an L shape gives the trapeze area 1/2 (1 - (2p + 1) / L) of "Morphological
 * antialiasing and topological reconstruction" (section 3.4) for the p-th pixel from its crossing
 * edge.
 *
 * Tables are computed once per D and shared by all instances (thread-safe). The CPU filter
 * vtkImageMLAA reads GetTable(); the GPU pass vtkOpenGLMLAAPass uploads the same table.
 *
 * @sa vtkMLAAOptions vtkImageMLAA vtkOpenGLMLAAPass
 */

#ifndef vtkMLAAAreaTexture_h
#define vtkMLAAAreaTexture_h

#include "vtkFiltersMLAAModule.h" // For export macro
#include "vtkObject.h"

#include <memory> // For std::shared_ptr
#include <vector> // For std::vector

class vtkImageData;

class VTKFILTERSMLAA_EXPORT vtkMLAAAreaTexture : public vtkObject
{
public:
  static vtkMLAAAreaTexture* New();
  vtkTypeMacro(vtkMLAAAreaTexture, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Number of crossing-edge codes, and so of cells along each side of the texture. */
  static constexpr int NumberOfCodes = 5;

  ///@{
  /**
   * Longest distance to an end of a line that the table covers, in pixels: D - 1. Default 16
   * (vtkMLAAOptions' default of 8 search steps), range [1, 1023].
   */
  vtkSetClampMacro(MaxDistance, int, 1, 1023);
  vtkGetMacro(MaxDistance, int);
  ///@}

  /** D, the side of one cell in texels: MaxDistance + 1. */
  int GetCellSize() const { return this->MaxDistance + 1; }

  /** Side of the whole texture in texels: 5 * D. */
  int GetTextureSize() const { return NumberOfCodes * this->GetCellSize(); }

  /**
   * The table for the current MaxDistance: GetTextureSize()^2 texels of two floats, texel (s, t)
   * at index 2 * (t * GetTextureSize() + s). Owned by a shared cache; valid while this object
   * lives and its MaxDistance is unchanged.
   */
  const float* GetTable();

  /**
   * The areas of texel (D * e1 + left, D * e2 + right) of the table: channel 0 or 1 (see the
   * class description). Out-of-range arguments give 0.
   */
  float GetArea(int e1, int e2, int left, int right, int channel);

  /**
   * The table as an 8-bit image, GetTextureSize() square, 3 components: red and green are the
   * two areas times 255, rounded; blue is 0. Rows are stored so that the image reads as
   * Figure 4.2 when written by an image writer (the texel row t = 0 is the top row of the file,
   * i.e. the vtkImageData row GetTextureSize() - 1). The returned object belongs to this one.
   */
  vtkImageData* GetImage();

  /**
   * The analytical areas, in double precision, without a table: areas[0] for the pixel that
   * owns the edgel, areas[1] for the pixel opposite. Codes other than 1 and 3 add no slope.
   * Distances must be non-negative.
   */
  static void ComputeAreas(int e1, int e2, int left, int right, double areas[2]);

  /**
   * The shared table for cells of side D = maxDistance + 1, computing it on first use.
   */
  static std::shared_ptr<const std::vector<float>> GetSharedTable(int maxDistance);

protected:
  vtkMLAAAreaTexture();
  ~vtkMLAAAreaTexture() override;

  int MaxDistance = 16;

private:
  vtkMLAAAreaTexture(const vtkMLAAAreaTexture&) = delete;
  void operator=(const vtkMLAAAreaTexture&) = delete;

  std::shared_ptr<const std::vector<float>> Table;
  int TableMaxDistance = 0;
  vtkImageData* Image = nullptr;
  int ImageMaxDistance = 0;
};

#endif
