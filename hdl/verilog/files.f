intersection_unit.v
patch_loader.v
