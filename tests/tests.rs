mod cli;
mod cosim;
mod figures;
mod hardware;
mod scene_loader;
mod tracers;
mod workstream;
