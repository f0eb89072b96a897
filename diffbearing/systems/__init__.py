"""Bearings mounted: a rigid or flexible shaft on several bearings, matched sets, fits and the
operating clearance they leave."""
