; Packing a box: it may be closed only once everything that belongs in it is inside
; (a forall precondition over an implication). Predicates are the household's, with paraphrases.
(define (domain packing)
  (:requirements :typing :negative-preconditions :universal-preconditions :disjunctive-preconditions)
  (:types item box surface)
  (:predicates (on ?o - item ?s - surface) (holding ?o - item) (hand_empty) (inside ?o - item ?b - box)
               (open ?b - box) (closed ?b - box) (belongs ?o - item ?b - box))
  (:action grasp
    :parameters (?o - item ?s - surface)
    :precondition (and (hand_empty) (on ?o ?s))
    :effect (and (holding ?o) (not (hand_empty)) (not (on ?o ?s))))
  (:action placein
    :parameters (?o - item ?b - box)
    :precondition (and (holding ?o) (open ?b))
    :effect (and (inside ?o ?b) (hand_empty) (not (holding ?o))))
  (:action close
    :parameters (?b - box)
    :precondition (and (open ?b) (hand_empty) (forall (?o - item) (imply (belongs ?o ?b) (inside ?o ?b))))
    :effect (and (closed ?b) (not (open ?b)))))
