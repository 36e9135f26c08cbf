mod scene_loader;
mod tracers;
