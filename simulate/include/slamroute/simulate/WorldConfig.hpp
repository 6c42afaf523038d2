#pragma once
// Parameters of the procedural 3D city built from a SUMO net (World). The paper drives CARLA's
// towns; we build our own city so that streets differ in how much structure a LiDAR sees.
#include <string>

namespace slamroute::simulate {

struct WorldConfig {
  std::string poly_file = "";  ///< SUMO .poly.xml with type="building" polygons; "" = procedural
  double ground_margin_m = 150.0;   ///< ground plane extends this far beyond the net [m]
  double sidewalk_width_m = 2.5;    ///< sidewalk beside the outermost lane [m]
  double curb_height_m = 0.15;      ///< sidewalk top above the road [m]
  double elevated_min_m = 2.5;      ///< a lane this far above the local ground is a bridge deck [m]
  double deck_thickness_m = 1.0;    ///< bridge deck thickness below the road surface [m]
  double parapet_height_m = 1.0;    ///< railing wall on bridge decks [m]
  double pillar_spacing_m = 18.0;   ///< distance between bridge pillars along the deck [m]
  double pillar_half_size_m = 0.6;  ///< half side of a square pillar [m]
  double junction_clearance_m = 6.0;  ///< no building/pole/tree within this of a junction shape [m]
  double road_clearance_m = 1.0;      ///< min gap between any building and any lane edge [m]
  double rich_share = 0.45;  ///< share of streets lined with varied buildings, poles, trees
  double wall_share = 0.2;   ///< share of streets lined with long uniform walls
  // the rest (1 - rich - wall) are open fields: nothing but the road and a few sparse poles
  double setback_min_m = 1.5;          ///< building front behind the sidewalk, min [m]
  double setback_max_m = 10.0;         ///< ... max [m]
  double frontage_min_m = 8.0;         ///< building length along the street, min [m]
  double frontage_max_m = 35.0;        ///< ... max [m]
  double building_depth_min_m = 8.0;   ///< building extent away from the street, min [m]
  double building_depth_max_m = 22.0;  ///< ... max [m]
  double height_min_m = 5.0;           ///< building height, min [m]
  double height_max_m = 35.0;          ///< ... max [m]
  double gap_max_m = 12.0;             ///< gap between neighbouring buildings, max [m]
  double wall_height_m = 3.0;          ///< uniform wall height on "wall" streets [m]
  double wall_setback_m = 3.0;         ///< uniform wall distance behind the sidewalk [m]
  double pole_spacing_m = 25.0;        ///< street-light pole spacing on rich streets [m]
  double tree_spacing_m = 14.0;        ///< tree spacing on rich streets (with jitter) [m]
  double open_pole_spacing_m = 80.0;   ///< pole spacing on open-field streets [m]
  // Relief of roads and ground: neither is a plane, so a LiDAR's ground rings differ from scan
  // to scan as on real roads, and the vehicle rolls and pitches over them.
  double road_camber_pct = 2.0;           ///< cross-fall from the road's crown to its kerbs [%]
  double undulation_m = 0.02;             ///< metres-long swell of road and ground, 1 sigma [m]
  double undulation_wavelength_m = 25.0;  ///< typical wavelength of the swell [m]
  double road_roughness_m = 0.006;        ///< roughness of roads and pavements, 1 sigma [m]
  double verge_roughness_m = 0.025;       ///< roughness of the ground beside roads, 1 sigma [m]
  double road_cell_m = 1.0;               ///< road mesh spacing along a lane (and ~across) [m]
  double ground_cell_m = 4.0;             ///< rough-ground mesh spacing near roads [m]
  double ground_detail_reach_m = 40.0;    ///< rough ground this far from any lane; flat beyond [m]
};

template <class V>
void visitFields(V& v, WorldConfig& c) {
  v.field("poly_file", c.poly_file, "SUMO .poly.xml buildings (type=building); empty = procedural");
  v.field("ground_margin_m", c.ground_margin_m, "ground plane margin beyond the net [m]");
  v.field("sidewalk_width_m", c.sidewalk_width_m, "sidewalk width [m]");
  v.field("curb_height_m", c.curb_height_m, "curb / sidewalk height [m]");
  v.field("elevated_min_m", c.elevated_min_m,
          "lane height above ground that makes a bridge deck [m]");
  v.field("deck_thickness_m", c.deck_thickness_m, "bridge deck thickness [m]");
  v.field("parapet_height_m", c.parapet_height_m, "bridge parapet height [m]");
  v.field("pillar_spacing_m", c.pillar_spacing_m, "bridge pillar spacing [m]");
  v.field("pillar_half_size_m", c.pillar_half_size_m, "bridge pillar half side [m]");
  v.field("junction_clearance_m", c.junction_clearance_m, "free space around junctions [m]");
  v.field("road_clearance_m", c.road_clearance_m, "min gap building to lane edge [m]");
  v.field("rich_share", c.rich_share, "share of feature-rich streets");
  v.field("wall_share", c.wall_share, "share of long-uniform-wall streets (rest: open field)");
  v.field("setback_min_m", c.setback_min_m, "building setback min [m]");
  v.field("setback_max_m", c.setback_max_m, "building setback max [m]");
  v.field("frontage_min_m", c.frontage_min_m, "building frontage min [m]");
  v.field("frontage_max_m", c.frontage_max_m, "building frontage max [m]");
  v.field("building_depth_min_m", c.building_depth_min_m, "building depth min [m]");
  v.field("building_depth_max_m", c.building_depth_max_m, "building depth max [m]");
  v.field("height_min_m", c.height_min_m, "building height min [m]");
  v.field("height_max_m", c.height_max_m, "building height max [m]");
  v.field("gap_max_m", c.gap_max_m, "max gap between buildings [m]");
  v.field("wall_height_m", c.wall_height_m, "uniform wall height [m]");
  v.field("wall_setback_m", c.wall_setback_m, "uniform wall setback [m]");
  v.field("pole_spacing_m", c.pole_spacing_m, "pole spacing on rich streets [m]");
  v.field("tree_spacing_m", c.tree_spacing_m, "tree spacing on rich streets [m]");
  v.field("open_pole_spacing_m", c.open_pole_spacing_m, "pole spacing on open-field streets [m]");
  v.field("road_camber_pct", c.road_camber_pct, "road cross-fall from crown to kerb [%]");
  v.field("undulation_m", c.undulation_m, "metres-long swell of road and ground, 1 sigma [m]");
  v.field("undulation_wavelength_m", c.undulation_wavelength_m, "typical swell wavelength [m]");
  v.field("road_roughness_m", c.road_roughness_m, "road / pavement roughness, 1 sigma [m]");
  v.field("verge_roughness_m", c.verge_roughness_m, "ground roughness beside roads, 1 sigma [m]");
  v.field("road_cell_m", c.road_cell_m, "road mesh spacing [m]");
  v.field("ground_cell_m", c.ground_cell_m, "rough-ground mesh spacing [m]");
  v.field("ground_detail_reach_m", c.ground_detail_reach_m, "rough ground this far from lanes [m]");
}

}  // namespace slamroute::simulate
