"""Designations (`bearing.designation`): a catalogue designation gives the bearing's boundary
dimensions d, D and B from ISO 15's dimension series (`diffbearing.catalog.designations`). The scene
layer sets them where the scene gives none (`app/scene.py`, `Scene.derived`), the report and the JSON
name where each came from; a value the scene gives overrides the designation's."""

from ...bearings.roller.roller_geometry import ROLLER_KINDS
from ...params import BALL_BEARING_KINDS
from ..registry import Adapter, Key, quantity, register

# the keys the scene layer reads (app/scene.py), not an input builder: in [bearing] and in a shaft's
# [[bearings]] entries
SCENE_LAYER_KEYS = ("bearing.designation", "bearing.static_load_rating")

ADAPTER = register(Adapter(
    name="designation",
    bearing_types=BALL_BEARING_KINDS + ROLLER_KINDS,
    keys={"bearing.designation": Key("text", doc="catalogue designation (6205, 7205 B, 22220 E, 61905), also in a "
                                                 "shaft's [[bearings]]: bore, outer_diameter and width from ISO 15's "
                                                 "dimension series where the scene gives none (`diffbearing bearings` "
                                                 "lists them); a deep groove or angular contact ball bearing's ball "
                                                 "set, groove ratios and clearance or contact angle (its suffix: B 40°, "
                                                 "AC 25°, A 30°, C 15°) estimated where it gives none"),
          "bearing.static_load_rating": quantity("force", "the catalogue's C0 (with bearing.designation and "
                                                          "bearing.dynamic_load_rating: the ball set that reproduces both)")},
))
