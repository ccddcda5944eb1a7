"""Galandrood mine (thesis §5.4.2) by limit equilibrium: Goodman and Bray and Aydan and Kawamoto on
BFTOP's input (Fig 5-44), beside BFTOP's block-flexure result. Prints JSON; needs no YADE.

    source scripts/env.sh; python3 examples/field/galandrood_lem.py

The layers dip 39° into the slope, so the columns' bases dip 51° and BFTOP's failure plane at 58°
lies 7° above the normal to the layers.
"""
from examples import params
from toppling.lem import flexural, goodman_bray
from toppling.lem.geometry import SlopeGeometry
from toppling.lem.report import json_text

fig = params.FIG_5_44
slope = SlopeGeometry(height=fig["height"], face_deg=fig["face_deg"], top_deg=fig["top_deg"],
                      joint_dip_deg=fig["layers_deg"], failure_plane_deg=fig["failure_plane_deg"] - (90 - fig["layers_deg"]),
                      spacing=fig["thickness"])
blocks = slope.blocks(fig["unit_weight"])
rock = flexural.Rock(fig["unit_weight"], fig["tensile_strength"], fig["friction_columns_deg"])
print(json_text(dict(columns=len(blocks.heights),
                     goodman_bray=goodman_bray.summary(blocks, fig["friction_columns_deg"], fig["friction_base_deg"]),
                     flexural=flexural.summary(slope, rock),
                     bftop_thesis=params.FIG_5_44_RESULT)))
