patch_loader.v
screener.v
intersection_unit.v
